"""deferred_workbench.temporal_error and tradeoff(metric="temporal") (issue 35
part 4), run by ctest with PYTHONPATH=<build>/python, DW_WORKBENCH_BINARY
naming the CLI and DW_REFERENCE_CACHE a cache both share. The temporal error
of arrays: the sub-pixel-moving edge's closed form (0.375 / 16 for pixel
centres against the box-filtered truth), 0 for the truth against itself, the
CLI's refusals as dw.Error; tradeoff(metric="temporal") along a short orbit
of small steps (1.8 degrees): the same numbers as `tradeoff --metric temporal --csv`, and
without a camera path the CLI's one line."""
import csv
import os
import subprocess
import tempfile
import unittest

import numpy as np

import deferred_workbench as dw

BINARY = os.environ["DW_WORKBENCH_BINARY"]


def edge_frames():
    """17 frames 16 x 4: an edge moving 0.25 px a frame; box-filtered truth and pixel centres."""
    truth, centres = [], []
    x = np.arange(16, dtype=np.float64)
    for t in range(17):
        edge = 2.125 + 0.25 * t
        truth.append(np.tile(np.clip(edge - x, 0.0, 1.0).astype(np.float32), (4, 1)))
        centres.append(np.tile((x + 0.5 < edge).astype(np.float32), (4, 1)))
    return truth, centres


KEYWORDS = dict(scene="default", size=(64, 36), sweep={"aa.method": ["none", "taa"]}, metric="temporal",
                orbit=9, orbit_degrees=16.0, ref_spp=16, ao_rays=4, frames=1, warmup=0,
                resamples=200, quiet=True)
FLAGS = ["tradeoff", "--scene", "default", "--size", "64x36", "--sweep", "aa.method=none,taa", "--metric",
         "temporal", "--orbit", "9", "--orbit-degrees", "16", "--ref-spp", "16", "--ao-rays", "4",
         "--frames", "1", "--warmup", "0", "--resamples", "200", "--quiet", "--plot", "none"]


class TemporalErrorTest(unittest.TestCase):
    def test_the_moving_edge_has_the_closed_form(self):
        truth, centres = edge_frames()
        r = dw.temporal_error(truth, centres)
        self.assertEqual(r["frames"], 17)
        self.assertEqual(len(r["pairs"]), 16)
        self.assertAlmostEqual(r["mean"], 0.375 / 16, places=12)
        self.assertAlmostEqual(r["pairs"][1], 0.75 / 16, places=12)  # frames 1 -> 2: the centres' jump
        self.assertLessEqual(r["low"], r["mean"])
        self.assertGreaterEqual(r["high"], r["mean"])
        # One T x H x W array is the same sequence.
        self.assertEqual(dw.temporal_error(np.stack(truth), np.stack(centres))["mean"], r["mean"])
        same = dw.temporal_error(truth, truth)
        self.assertEqual((same["mean"], same["low"], same["high"]), (0.0, 0.0, 0.0))

    def test_bad_sequences_raise_naming_the_frame(self):
        truth, centres = edge_frames()
        with self.assertRaises(dw.Error) as caught:
            dw.temporal_error(truth, centres[:-1])
        self.assertIn("the reference has 17 frames, the test 16", str(caught.exception))
        with self.assertRaises(dw.Error) as caught:
            dw.temporal_error(truth, centres[:5] + [np.zeros((4, 8), np.float32)] + centres[6:])
        self.assertIn("test frame 5 is 8x4x1, reference frame 0 is 16x4x1", str(caught.exception))
        with self.assertRaises(dw.Error) as caught:
            dw.temporal_error(truth[:1], centres[:1])
        self.assertIn("needs at least 2 frames", str(caught.exception))


class TradeoffTemporalTest(unittest.TestCase):
    def test_the_same_numbers_as_the_cli_and_none_flickers_more_than_taa(self):
        record = dw.tradeoff(**KEYWORDS)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "cli.csv")
            done = subprocess.run([BINARY] + FLAGS + ["--csv", path, "--record", os.path.join(tmp, "cli.json")],
                                  capture_output=True, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(path) as f:
                cli = list(csv.DictReader(f))
        rows = record["rows"]
        self.assertEqual(len(rows), 2 * 10)  # 2 points x (9 cameras + all)
        every = {r["aa.method"]: r for r in rows if r["camera"] == "all"}
        for method, row in every.items():
            self.assertEqual(row["metric"], "temporal")
            self.assertLessEqual(row["error_lo"], row["error"], method)
            self.assertGreaterEqual(row["error_hi"], row["error"], method)
        self.assertGreater(every["none"]["error"], every["taa"]["error"])
        for mine, theirs in zip(rows, cli):
            if mine["camera"] == "all":
                self.assertEqual(mine["error"], float(theirs["error"]))

    def test_without_a_camera_path_it_is_refused(self):
        with self.assertRaises(ValueError) as caught:  # TradeoffStudy::check's, as every bad keyword
            dw.tradeoff(**dict(KEYWORDS, orbit=0, orbit_degrees=None))
        self.assertIn("--metric temporal measures the change from frame to frame along a camera path",
                      str(caught.exception))


if __name__ == "__main__":
    unittest.main()
