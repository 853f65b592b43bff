"""Importing deferred_workbench (issue 32): a Python without numpy is told so
at import, in one line naming numpy and the interpreter (it used to import
and fail at the first render); __version__ and __commit__ are the build's,
the same as the build fields a record of this build holds."""
import json
import os
import re
import subprocess
import sys
import tempfile
import unittest

BINARY = os.environ["DW_WORKBENCH_BINARY"]


class ImportTest(unittest.TestCase):
    def test_without_numpy_the_import_fails_naming_numpy_and_the_interpreter(self):
        # -S leaves out site-packages, where Debian's numpy is; PYTHONPATH still finds the module.
        r = subprocess.run([sys.executable, "-S", "-c", "import deferred_workbench"], capture_output=True, text=True,
                           timeout=120)
        self.assertNotEqual(r.returncode, 0, r.stdout)
        last = r.stderr.strip().splitlines()[-1]
        self.assertTrue(last.startswith("ImportError: deferred_workbench needs numpy, which " + sys.executable +
                                        " cannot import (No module named 'numpy')"), r.stderr)
        # With numpy the same interpreter imports it.
        ok = subprocess.run([sys.executable, "-c", "import deferred_workbench"], capture_output=True, text=True,
                            timeout=120)
        self.assertEqual(ok.returncode, 0, ok.stderr)

    def test_version_and_commit_are_the_builds(self):
        import deferred_workbench as dw
        with tempfile.TemporaryDirectory() as tmp:
            record = os.path.join(tmp, "r.json")
            r = subprocess.run([BINARY, "render", "--scene", "default", "--size", "16x9", "--out",
                                os.path.join(tmp, "a.png"), "--record", record], capture_output=True, text=True,
                               timeout=300)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(record) as f:
                build = json.load(f)["build"]
        self.assertEqual(dw.__commit__, build["commit"])
        if build["commit"] == "unknown":
            self.assertEqual(dw.__version__, build["version"])
        else:
            self.assertEqual(dw.__version__, build["version"] + "+" + re.sub(r"[^A-Za-z0-9]", ".", build["commit"]))
        self.assertRegex(dw.__version__, r"^\d+\.\d+(\.\d+)?(\+[A-Za-z0-9.]+)?$")


if __name__ == "__main__":
    unittest.main()
