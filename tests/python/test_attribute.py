"""deferred_workbench.attribute (issue 34 part 4), run by ctest with
PYTHONPATH=<build>/python, DW_WORKBENCH_BINARY naming the CLI and
DW_REFERENCE_CACHE a cache both share: the same numbers as `tradeoff
--attribute --csv` of the same view, a part for every family with its
interval, and bad arguments raising ValueError with the CLI's message."""
import csv
import math
import os
import subprocess
import tempfile
import unittest

import deferred_workbench as dw

BINARY = os.environ["DW_WORKBENCH_BINARY"]
KEYWORDS = dict(scene="default", size=(64, 36), metric="rms", buffer="lbuffer", ao_rays=16, resamples=200, quiet=True)
FLAGS = ["tradeoff", "--attribute", "--scene", "default", "--size", "64x36", "--metric", "rms", "--buffer", "lbuffer",
         "--ao-rays", "16", "--resamples", "200", "--quiet", "--plot", "none"]


class AttributeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.csv = os.path.join(cls.tmp.name, "py.csv")
        cls.result = dw.attribute(csv=cls.csv, **KEYWORDS)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_same_numbers_as_the_cli(self):
        out = os.path.join(self.tmp.name, "cli.csv")
        subprocess.run([BINARY] + FLAGS + ["--csv", out], check=True, capture_output=True, text=True)
        with open(out) as f:
            cli = {r["row"]: r for r in csv.DictReader(f)}
        with open(self.csv) as f:
            mine = {r["row"]: r for r in csv.DictReader(f)}
        self.assertEqual(cli, mine)
        self.assertAlmostEqual(self.result["as_is"]["value"], float(cli["as_is"]["error"]), delta=1e-5 * float(cli["as_is"]["error"]))

    def test_every_family_has_its_parts_with_intervals(self):
        names = [f["name"] for f in self.result["families"]]
        self.assertEqual(names, ["shadows", "ao", "light_cutoff", "gbuffer", "texture_filter", "transparency", "bloom",
                                 "dof", "aa"])
        for f in self.result["families"]:
            for part in ("removed", "added"):
                p = f[part]
                self.assertTrue(p["low"] <= p["value"] <= p["high"], (f["name"], part, p))
        total = self.result["total"]["value"]
        self.assertAlmostEqual(total, self.result["as_is"]["value"] - self.result["all_exact"]["value"], delta=1e-9)
        fxaa = next(f for f in self.result["families"] if f["name"] == "aa")
        self.assertEqual(fxaa["removed"]["value"], 0.0)  # FXAA acts after the L-buffer
        self.assertIn("| ao | only exact", self.result["table"])

    def test_bad_arguments_raise_with_the_cli_message(self):
        with self.assertRaisesRegex(ValueError, "flip or rms, got 'ssim'"):
            dw.attribute(**dict(KEYWORDS, metric="ssim"))
        with self.assertRaisesRegex(ValueError, "expected final, lbuffer, ao or shadow"):
            dw.attribute(**dict(KEYWORDS, buffer="nope"))
        with self.assertRaises(ValueError):
            dw.attribute(**dict(KEYWORDS, size=(0, 36)))


if __name__ == "__main__":
    unittest.main()
