"""scripts/counter_rank.py, the rank correlation docs/tradeoffs.md prints
("Cost counters against measured GPU ms"), on a small real bench run (two
AO resolutions x two sample counts at 64x36): the frame and ao rows, a
correlation in [-1, 1] or "-" for a counter that is the same everywhere; and
on a synthetic CSV whose answer is known (ranks in order: 1; reversed: -1;
ties averaged). A CSV without counter columns is refused in one line."""
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "counter_rank.py")
BINARY = os.environ["DW_WORKBENCH_BINARY"]
HEADER = "config,size,lights,lpp,lpp_lit,sample,seq,frame,pass,gpu_ms,cpu_ms,fragments,samples,primitives,vertices,compute,bytes\n"


def rank(csv_path, *passes):
    args = [sys.executable, SCRIPT, "--csv", csv_path]
    for p in passes:
        args += ["--pass", p]
    return subprocess.run(args, capture_output=True, text=True)


class CounterRankTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, name, text):
        path = os.path.join(self.tmp.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_known_correlations(self):
        # fragments rise with the time (rho 1), samples fall (-1), bytes the same everywhere (-).
        lines = [HEADER]
        for config, ms in enumerate([1.0, 2.0, 3.0, 4.0]):
            lines.append("%d,8x8,0,,,0,%d,%d,frame,%g,0,%d,%d,1,3,0,64\n" % (config, config, config, ms, 10 * config, 5 - config))
        r = rank(self.write("k.csv", "".join(lines)))
        self.assertEqual(r.returncode, 0, r.stderr)
        row = r.stdout.splitlines()[1].split()
        self.assertEqual(row[:2], ["frame", "4"])
        self.assertEqual(row[2:], ["1.000", "-1.000", "-", "-", "-", "-"])

    def test_a_real_bench_run(self):
        csv_path = os.path.join(self.tmp.name, "b.csv")
        run = subprocess.run([BINARY, "bench", "--scene", "default", "--size", "64x36", "--sweep", "ssao.samples=4,16",
                              "--sweep", "ssao.resolution=full,half", "--frames", "2", "--no-lpp", "--quiet",
                              "--csv", csv_path, "--record", os.path.join(self.tmp.name, "b.json")],
                             capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("cost counters: the same in every counted frame of each configuration", run.stdout)
        r = rank(csv_path, "ao")
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.splitlines()
        self.assertEqual([l.split()[0] for l in lines[1:]], ["frame", "ao"])
        for line in lines[1:]:
            cells = line.split()
            self.assertEqual(cells[1], "4")
            for cell in cells[2:]:
                self.assertTrue(cell == "-" or -1.0 <= float(cell) <= 1.0, line)

    def test_without_counters_is_refused(self):
        path = self.write("n.csv", HEADER.split(",fragments")[0] + "\n")
        r = rank(path)
        self.assertEqual(r.returncode, 2)
        self.assertIn("not a bench samples CSV with counter columns", r.stderr)


if __name__ == "__main__":
    unittest.main()
