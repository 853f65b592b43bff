"""scripts/ao_methods_plot.py (issue 22's AO Pareto study): the joint front
over several methods' tradeoff CSVs on the AO passes' time, the cheapest
point of each method at the target's error, --only, and a bad CSV refused
with exit 2; the labels of scripts/plot_labels.py (shared with
tradeoff_plot.py) overlapping no other label, no point and no line, in the
AO plot too. Synthetic CSVs; no GL."""
import importlib.util
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "ao_methods_plot.py")
sys.path.insert(0, os.path.dirname(SCRIPT))  # plot_labels and ao_methods_plot as modules
HAVE_MATPLOTLIB = importlib.util.find_spec("matplotlib") is not None
HEAD = ("point,{axes},camera,metric,buffer,error,error_lo,error_hi,frames,frame_gpu_ms,frame_gpu_ms_lo,"
        "frame_gpu_ms_hi,gpu_ms.ao,gpu_ms.ao_filter,pareto\n")


def write(folder, name, axes, rows, metric="rms", buffer="ao"):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(HEAD.format(axes=",".join(axes)))
        for i, (values, error, ao, filt) in enumerate(rows):
            for cam in ("0", "all"):
                f.write(f"{i},{','.join(values)},{cam},{metric},{buffer},{error},,,3,100,90,110,{ao},{filt},0\n")
    return path


class AoMethodsPlotTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        d = self.tmp.name
        self.ssao = write(d, "ssao.csv", ["ssao.samples", "ssao.resolution"],
                          [(("16", "half"), 0.06, 5, 2), (("4", "half"), 0.059, 3, 1), (("8", "quarter"), 0.07, 1, 0.5)])
        self.gtao = write(d, "gtao.csv", ["gtao.slices"], [(("2",), 0.05, 4, 1), (("1",), 0.08, 2, 1)])
        self.aov = write(d, "aov.csv", ["aov.radius"], [(("1",), 0.02, 500, 0), (("0.5",), 0.01, 100, 0)])

    def tearDown(self):
        self.tmp.cleanup()

    def run_script(self, *extra):
        out = os.path.join(self.tmp.name, "p.png")
        r = subprocess.run([sys.executable, SCRIPT, "--out", out, *extra], capture_output=True, text=True)
        return r, out

    def test_front_and_target_table(self):
        r, out = self.run_script("--only", "aov.radius=1", f"ssao={self.ssao}", f"gtao={self.gtao}", f"aov={self.aov}")
        self.assertIn(r.returncode, (0, 3), r.stderr)  # 3: matplotlib missing, the tables are printed first
        front, _, target = r.stdout.partition("At the error")
        rows = [line for line in front.splitlines() if line.startswith("| ssao") or line.startswith("| gtao")
                or line.startswith("| aov")]
        # 8,quarter (1.5 ms), 4,half (4 ms, 0.059), gtao 2 (5 ms, 0.05), aov r=1 (500, 0.02); 16,half and
        # gtao 1 are beaten; aov r=0.5 is left out by --only.
        self.assertEqual([row.split("|")[2].strip() for row in rows],
                         ["ssao.samples=8,ssao.resolution=quarter", "ssao.samples=4,ssao.resolution=half",
                          "gtao.slices=2", "aov.radius=1"])
        self.assertIn("(0.0600)", target)
        self.assertIn("| ssao | ssao.samples=4,ssao.resolution=half | 4.00 |", target)
        self.assertIn("| gtao | gtao.slices=2 | 5.00 |", target)
        self.assertIn("| 0.71 |", target)  # 5 ms / the target's 7 ms
        if r.returncode == 0:
            self.assertGreater(os.path.getsize(out), 1000)

    def test_errors_table_and_plot_error(self):
        # FLIP of the final image from an untimed run (its ms are not used): the order of the errors reversed,
        # and one point (8,quarter) missing.
        flip = write(self.tmp.name, "ssao-flip-final.csv", ["ssao.samples", "ssao.resolution"],
                     [(("16", "half"), 0.02, 900, 900), (("4", "half"), 0.03, 900, 900)], "flip", "final")
        r, _ = self.run_script(f"ssao={self.ssao}", f"gtao={self.gtao}", "--errors", f"ssao={flip}",
                               "--plot-error", "flip:final")
        self.assertIn(r.returncode, (0, 3), r.stderr)
        table, _, rest = r.stdout.partition("Joint Pareto front")
        self.assertIn("| ssao.samples | ssao.resolution | AO passes ms | rms (ao) | flip (final) |", table)
        self.assertIn("| 16 | half | 7.00 | 0.0600 | 0.0200 |", table)
        self.assertIn("| 8 | quarter | 1.50 | 0.0700 |  |", table)
        self.assertIn("against the flip of final", rest)
        # Only ssao's two points with a FLIP: 4,half (4 ms, 0.03) and 16,half (7 ms, 0.02) both on the front,
        # timed by the main CSV; gtao has no flip:final and is left out.
        front = [line for line in rest.partition("At the error")[0].splitlines() if line.startswith("| ssao")
                 or line.startswith("| gtao")]
        self.assertEqual([row.split("|")[2].strip() for row in front],
                         ["ssao.samples=4,ssao.resolution=half", "ssao.samples=16,ssao.resolution=half"])
        self.assertIn("| 7.00 |", front[1])
        r, _ = self.run_script(f"ssao={self.ssao}", "--errors", f"ssao={flip}", "--plot-error", "flip:ao")
        self.assertEqual(r.returncode, 2)
        self.assertIn("flip:ao", r.stderr)
        r, _ = self.run_script(f"ssao={self.ssao}", "--errors", f"aov={flip}")
        self.assertEqual(r.returncode, 2)
        self.assertIn("'aov'", r.stderr)

    def test_bad_csv_is_refused(self):
        bad = os.path.join(self.tmp.name, "bad.csv")
        with open(bad, "w") as f:
            f.write("a,b\n1,2\n")
        r, _ = self.run_script(f"ssao={bad}")
        self.assertEqual(r.returncode, 2)
        self.assertIn("bad.csv", r.stderr)


class BenchPassBarsTest(unittest.TestCase):
    """scripts/bench_pass_bars.py: draws a bench JSON's pass medians; a file that is not one is refused (2)."""

    def test_draws_and_refuses(self):
        import json
        script = os.path.join(os.path.dirname(SCRIPT), "bench_pass_bars.py")
        with tempfile.TemporaryDirectory() as d:
            good, bad, out = (os.path.join(d, n) for n in ("b.json", "x.json", "b.png"))
            configs = [{"size": size, "knobs": {"tonemap.operator": op},
                        "series": {"tonemap": {"gpu_ms": {"median": 1.0}}, "luminance": {"gpu_ms": {"median": 3.0}}}}
                       for size in ("160x90", "320x180") for op in ("simple", "reinhard")]
            with open(good, "w") as f:
                json.dump({"results": {"configs": configs}}, f)
            with open(bad, "w") as f:
                f.write("{}")
            r = subprocess.run([sys.executable, script, "--json", good, "--passes", "tonemap,luminance", "--out", out],
                               capture_output=True, text=True)
            self.assertIn(r.returncode, (0, 3), r.stderr)
            if r.returncode == 0:
                self.assertGreater(os.path.getsize(out), 1000)
            r = subprocess.run([sys.executable, script, "--json", bad, "--passes", "ao", "--out", out],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 2)
            self.assertIn("x.json", r.stderr)


def overlap(a, b):
    """Area (square pixels) two (x0, y0, x1, y1) boxes share."""
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return w * h if w > 0 and h > 0 else 0.0


@unittest.skipUnless(HAVE_MATPLOTLIB, "matplotlib is missing (apt-get install python3-matplotlib)")
class PlotLabelsTest(unittest.TestCase):
    """place_labels: a cluster of points whose labels, each right above its point, would cover each other and
    the neighbours' points gets labels that cover nothing, inside the axes, and avoid a line."""

    def setUp(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        self.plt = plt
        self.fig, self.ax = plt.subplots(figsize=(4, 3), dpi=100)
        # Three points 6 pixels apart (the bunny's ssao 4,full / gtao 4,4,full / gtao 2,4,full) and one alone.
        self.points = [(10.0, 1.0), (10.2, 0.98), (10.4, 0.96), (2.0, 0.2)]
        self.ax.scatter([p[0] for p in self.points], [p[1] for p in self.points], s=22)
        self.ax.set_xlim(0, 20)
        self.ax.set_ylim(0, 2)
        self.fig.tight_layout()
        self.labels = [(x, y, f"method {i},settings", "black") for i, (x, y) in enumerate(self.points)]

    def tearDown(self):
        self.plt.close(self.fig)

    def px(self, point):
        return self.ax.transData.transform(point)

    def test_the_cluster_would_collide_and_does_not(self):
        from plot_labels import place_labels
        # Right above each point, 6 points away (the old fixed offset): the cluster's labels overlap.
        self.fig.canvas.draw()
        renderer = self.fig.canvas.get_renderer()
        naive = []
        for x, y, text, _ in self.labels[:3]:
            e = self.ax.annotate(text, (x, y), xytext=(6, 6), textcoords="offset points", fontsize=8).get_window_extent(renderer)
            naive.append((e.x0, e.y0, e.x1, e.y1))
        self.assertGreater(overlap(naive[0], naive[1]), 0)
        for t in list(self.ax.texts):
            t.remove()

        boxes = place_labels(self.ax, self.fig, self.labels, self.points)
        self.assertEqual(len(boxes), 4)
        area = self.ax.get_window_extent(renderer)
        pad = 3.0 * self.fig.dpi / 72.0
        for i, box in enumerate(boxes):
            self.assertTrue(area.x0 <= box[0] and box[2] <= area.x1 and area.y0 <= box[1] and box[3] <= area.y1, box)
            for other in boxes[:i]:
                self.assertEqual(overlap(box, other), 0.0, (box, other))
            for p in self.points:
                px, py = self.px(p)
                self.assertEqual(overlap(box, (px - pad, py - pad, px + pad, py + pad)), 0.0, (box, p))
        # The lone point keeps the usual place: right above it, about 6 points away.
        px, py = self.px(self.points[3])
        self.assertAlmostEqual(boxes[3][0] - px, 6 * self.fig.dpi / 72.0, delta=1.0)
        self.assertAlmostEqual(boxes[3][1] - py, 6 * self.fig.dpi / 72.0, delta=1.0)
        # Moved labels get a leader line each (annotations without text), the lone one none.
        leaders = [t for t in self.ax.texts if t.get_text() == ""]
        self.assertGreaterEqual(len(leaders), 1)
        self.assertLessEqual(len(leaders), 3)

    def test_a_line_is_avoided(self):
        from plot_labels import place_labels
        # A line through where the lone point's label would go (right above it).
        x, y = self.points[3]
        line = [(x, y + 0.1), (x + 6, y + 0.1)]
        box = place_labels(self.ax, self.fig, self.labels[3:], self.points, [line])[0]
        (x0, ly), (x1, _) = self.px(line[0]), self.px(line[1])
        self.assertFalse(box[1] <= ly <= box[3] and box[0] < x1 and box[2] > x0, (box, ly))


@unittest.skipUnless(HAVE_MATPLOTLIB, "matplotlib is missing (apt-get install python3-matplotlib)")
class AoMethodsPlotLabelsTest(unittest.TestCase):
    """ao_methods_plot.py labels its front through place_labels: with a cluster of front points its labels
    overlap neither each other nor any point."""

    def test_front_labels_do_not_collide(self):
        import ao_methods_plot
        import plot_labels
        calls = []

        def recording(ax, fig, labels, points, lines=(), **kw):
            boxes = plot_labels.place_labels(ax, fig, labels, points, lines, **kw)
            calls.append((labels, points, boxes, fig.dpi, ax.transData.transform))
            return boxes

        with tempfile.TemporaryDirectory() as d:
            # Three points on the front within 10% of each other's time and error, as on the bunny.
            ssao = write(d, "ssao.csv", ["ssao.samples"], [(("4",), 0.0111, 15, 1), (("8",), 0.0122, 20, 1)])
            gtao = write(d, "gtao.csv", ["gtao.slices"], [(("2",), 0.0108, 17, 1), (("4",), 0.0107, 18, 1)])
            argv, place = sys.argv, ao_methods_plot.place_labels
            sys.argv = ["ao_methods_plot.py", "--out", os.path.join(d, "p.png"), f"ssao={ssao}", f"gtao={gtao}"]
            ao_methods_plot.place_labels = recording
            try:
                with open(os.devnull, "w") as null:
                    stdout, sys.stdout = sys.stdout, null
                    try:
                        self.assertEqual(ao_methods_plot.main(), 0)
                    finally:
                        sys.stdout = stdout
            finally:
                sys.argv, ao_methods_plot.place_labels = argv, place
        self.assertEqual(len(calls), 1)
        labels, points, boxes, dpi, to_px = calls[0]
        self.assertEqual([t for _, _, t, _ in labels], ["ssao 4", "gtao 2", "gtao 4"])
        self.assertEqual(len(points), 4)
        pad = 2.5 * dpi / 72.0
        for i, box in enumerate(boxes):
            for other in boxes[:i]:
                self.assertEqual(overlap(box, other), 0.0)
            for p in points:
                px, py = to_px(p)
                self.assertEqual(overlap(box, (px - pad, py - pad, px + pad, py + pad)), 0.0)


if __name__ == "__main__":
    unittest.main()
