"""deferred_workbench.tradeoff (issue 24), run by ctest with
PYTHONPATH=<build>/python, DW_WORKBENCH_BINARY naming the CLI and
DW_REFERENCE_CACHE a cache both share. A small SSAO sweep: its rows equal
`tradeoff --csv` of the same configuration (errors equal; times are not
compared), its front is a subset of the rows and non-dominated, the AO error
falls from 4 to 64 samples (ssao_blur.mode=off, RMS against the ray-traced AO),
the files it is asked for are written, and bad arguments raise with the CLI's
messages, never crash."""
import csv
import json
import math
import os
import subprocess
import tempfile
import threading
import unittest

import deferred_workbench as dw

BINARY = os.environ["DW_WORKBENCH_BINARY"]
SIZE = (64, 36)
SAMPLES = [4, 16, 64]
# The same study as keywords and as the CLI's flags.
KEYWORDS = dict(scene="default", size=SIZE, settings={"ssao_blur.mode": "off"}, sweep={"ssao.samples": SAMPLES},
                metric="rms", buffer="ao", frames=2, warmup=1, resamples=200, quiet=True)
FLAGS = ["tradeoff", "--scene", "default", "--size", "%dx%d" % SIZE, "--set", "ssao_blur.mode=off",
         "--sweep", "ssao.samples=" + ",".join(str(s) for s in SAMPLES), "--metric", "rms", "--buffer", "ao",
         "--frames", "2", "--warmup", "1", "--resamples", "200", "--quiet"]


def dominated(a, b):
    """Whether row b is at least as fast and as accurate as a, and better in one."""
    return (b["frame_gpu_ms"] <= a["frame_gpu_ms"] and b["error"] <= a["error"]
            and (b["frame_gpu_ms"] < a["frame_gpu_ms"] or b["error"] < a["error"]))


class TradeoffTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.csv = os.path.join(cls.tmp.name, "py.csv")
        cls.json = os.path.join(cls.tmp.name, "py.json")
        cls.plot = os.path.join(cls.tmp.name, "py.png")
        # On this (the main) thread first: the GL context is this thread's.
        cls.lines = []
        cls.record = dw.tradeoff(csv=cls.csv, json=cls.json, plot=cls.plot, **dict(KEYWORDS, quiet=False,
                                 progress=cls.lines.append))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_rows_equal_the_cli_csv(self):
        out = os.path.join(self.tmp.name, "cli.csv")
        subprocess.run([BINARY] + FLAGS + ["--csv", out, "--json", os.path.join(self.tmp.name, "cli.json"),
                                           "--plot", os.path.join(self.tmp.name, "cli.png")],
                       check=True, capture_output=True, text=True)
        with open(out) as f:
            cli = list(csv.DictReader(f))
        rows = self.record["rows"]
        self.assertEqual(len(rows), len(SAMPLES))
        self.assertEqual(len(cli), len(rows))
        self.assertEqual(list(rows[0].keys()), list(cli[0].keys()))  # the CSV's columns, in order
        for mine, theirs in zip(rows, cli):
            for key in ("point", "ssao.samples", "camera", "metric", "buffer", "frames"):
                self.assertEqual(str(mine[key]), theirs[key], key)
            for key in ("error", "error_lo", "error_hi"):
                self.assertEqual(mine[key], float(theirs[key]), key)  # the same images, the same numbers
            self.assertGreater(mine["frame_gpu_ms"], 0.0)
            self.assertIsInstance(mine["pareto"], bool)
        # The CSV Python wrote is the same table.
        with open(self.csv) as f:
            written = list(csv.DictReader(f))
        self.assertEqual([r["error"] for r in written], [r["error"] for r in cli])

    def test_counters_in_the_rows_and_cost_chooses_the_front(self):
        # Every row carries the frame's counters and each pass's; exact, so a second
        # run with cost="fragments" has the same ones, and its front is by fragments.ao.
        rows = self.record["rows"]
        for row in rows:
            self.assertGreater(row["fragments"], 0)
            self.assertGreater(row["fragments.ao"], 0)
            self.assertGreater(row["bytes"], 0)
        # budget= bounds the counter cost= names (of time='s span), exactly: the pick is the least error under it.
        budget = min(row["fragments.ao"] for row in rows) + 1
        again = dw.tradeoff(**dict(KEYWORDS, cost="fragments", time="ao", budget=budget))
        fits = [row for row in again["rows"] if row["fragments.ao"] < budget]
        self.assertTrue(fits)
        self.assertEqual(again["pick"]["budget"], budget)
        self.assertEqual(again["pick"]["row"]["error"], min(row["error"] for row in fits))
        for row in again["rows"]:
            self.assertEqual(row["pick"] == "over", row["fragments.ao"] >= budget, row["point"])
        for mine, theirs in zip(rows, again["rows"]):
            for key in mine:
                if key.split(".")[0] in ("fragments", "samples", "primitives", "vertices", "compute", "bytes"):
                    same = (math.isnan(mine[key]) and math.isnan(theirs[key])) or mine[key] == theirs[key]
                    self.assertTrue(same, key)
        front = {r["point"] for r in again["front"]}
        for a in again["rows"]:
            beaten = any(b["fragments.ao"] <= a["fragments.ao"] and b["error"] <= a["error"]
                         and (b["fragments.ao"] < a["fragments.ao"] or b["error"] < a["error"]) for b in again["rows"])
            self.assertEqual(a["point"] in front, not beaten, a["point"])

    def test_the_error_falls_with_the_samples(self):
        rows = {int(r["ssao.samples"]): r for r in self.record["rows"]}
        self.assertEqual(sorted(rows), SAMPLES)
        for r in rows.values():
            self.assertEqual((r["metric"], r["buffer"], r["camera"]), ("rms", "ao", "0"))
            self.assertLessEqual(r["error_lo"], r["error"])
            self.assertLessEqual(r["error"], r["error_hi"])
        # From 4 to 64 kernel samples, less noise against the ray-traced AO (as the CLI's test
        # asserts; what is left is mostly the estimator's bias, so neighbouring sample counts can
        # swap: at 160x90, 16 samples measure a little above 4).
        self.assertGreater(rows[4]["error"], rows[64]["error"])

    def test_the_front_is_the_non_dominated_rows(self):
        rows, front = self.record["rows"], self.record["front"]
        self.assertGreater(len(front), 0)
        for f in front:
            self.assertIn(f, rows)
            self.assertTrue(f["pareto"])
            for r in rows:
                self.assertFalse(dominated(f, r), (f, r))
        # Every row off the front is dominated by one on it (the front is all of it).
        for r in rows:
            if not r["pareto"]:
                self.assertTrue(any(dominated(r, f) for f in front), r)
        # The most accurate row is on it.
        best = min(rows, key=lambda r: r["error"])
        self.assertTrue(best["pareto"])

    def test_record_files_and_progress(self):
        r = self.record
        self.assertEqual((r["format"], r["command"]), ("deferred-workbench record", "tradeoff"))
        with open(self.json) as f:
            written = json.load(f)
        self.assertEqual(written, {k: v for k, v in r.items() if k not in ("rows", "front", "front_rule")})
        self.assertEqual(r["knobs"]["ssao_blur.mode"], "off")
        self.assertEqual(r["grid"]["axes"][0]["name"], "ssao.samples")
        self.assertEqual(len(r["results"]["rows"]), len(SAMPLES))
        self.assertEqual(r["results"]["settings"]["metric"], "rms")
        self.assertEqual(r["results"]["settings"]["frames"], "2")
        self.assertIn("gl_renderer", r["results"]["machine"])
        with open(self.plot, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertTrue(any(line.startswith("tradeoff: ") for line in self.lines), self.lines)

    def test_a_plot_alone_leaves_no_csv_behind(self):
        folder = os.path.join(self.tmp.name, "alone")
        os.mkdir(folder)
        r = dw.tradeoff(plot=os.path.join(folder, "p.png"), **dict(KEYWORDS, sweep={"ssao.samples": [4, 8]}, frames=1))
        self.assertEqual(len(r["rows"]), 2)
        self.assertEqual(os.listdir(folder), ["p.png"])

    def test_presets_axis_exclude_and_against_a_configuration(self):
        # presets and exclude as the flags write them (one str), the error against ssao.samples=64.
        r = dw.tradeoff(scene="default", size=(32, 18), presets="SSAO1,SSAO2", sweep={"ssao.samples": [4, 8]},
                        exclude="preset=SSAO2,ssao.samples=8", against="ssao.samples=64", metric="rms", buffer="ao",
                        frames=1, warmup=0, resamples=100, quiet=True)
        self.assertEqual([(x["point"], x["preset"], x["ssao.samples"]) for x in r["rows"]],
                         [(0, "SSAO1", "4"), (1, "SSAO1", "8"), (2, "SSAO2", "4")])  # point 3 left out
        self.assertEqual(list(r["rows"][0])[:4], ["point", "preset", "ssao.samples", "camera"])
        self.assertEqual(r["grid"]["against"], ["ssao.samples=64"])
        self.assertEqual(r["grid"]["exclude"], ["preset=SSAO2,ssao.samples=8"])
        self.assertNotIn("references_rendered", r["results"]["settings"])  # no CPU reference needed
        for x in r["rows"]:
            self.assertGreater(x["error"], 0.0)

    def test_scene_time_and_animation_as_the_cli_takes_them(self):
        # scene_time= and animation= (issue 36) on tradeoff and bench, as --scene-time and --animation: the
        # records keep them, and a time out of --scene-time's range raises with the CLI's words.
        skin = "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf"
        kw = dict(scene=skin, size=(32, 18), sweep={"aa.method": ["none"]}, metric="rms", ao_rays=2, frames=1,
                  warmup=0, resamples=100, quiet=True)
        posed = dw.tradeoff(scene_time=0.5, **kw)
        self.assertEqual(posed["scene_time"], 0.5)
        still = dw.tradeoff(scene_time=0.5, animation="none", **kw)
        self.assertEqual(still["animation"], "none")
        bench = dw.bench(scene=skin, sizes=[(32, 18)], frames=1, warmup=0, scene_time=0.25)
        self.assertEqual(bench["scene_time"], 0.25)
        with self.assertRaises(ValueError) as caught:
            dw.tradeoff(scene_time=-1, **kw)
        self.assertIn("--scene-time", str(caught.exception))

    def test_reference_samples_per_pixel(self):
        # ref_spp (issue 35) traces the reference over each pixel's area, as tradeoff --ref-spp: the record keeps
        # it and the filter, the errors are the CLI's for the same flags, and they are not the pixel centre's.
        kw = dict(scene="default", size=(32, 18), sweep={"gbuffer.texture_filter": ["mipmap", "base_level"]},
                  metric="rms", ao_rays=2, frames=1, warmup=0, resamples=100, quiet=True)
        four = dw.tradeoff(ref_spp=4, ref_filter="tent", **kw)
        self.assertEqual(four["grid"]["ref_spp"], 4)
        self.assertEqual(four["grid"]["ref_filter"], "tent")
        one = dw.tradeoff(**kw)
        self.assertEqual(one["grid"]["ref_spp"], 1)
        self.assertEqual(one["grid"]["ref_filter"], "box")
        self.assertNotEqual([x["error"] for x in four["rows"]], [x["error"] for x in one["rows"]])
        out = os.path.join(self.tmp.name, "spp.csv")
        subprocess.run([BINARY, "tradeoff", "--scene", "default", "--size", "32x18", "--sweep",
                        "gbuffer.texture_filter=mipmap,base_level", "--metric", "rms", "--ao-rays", "2", "--frames", "1",
                        "--warmup", "0", "--resamples", "100", "--quiet", "--ref-spp", "4", "--ref-filter", "tent",
                        "--csv", out, "--json", os.path.join(self.tmp.name, "spp.json"), "--plot", "none"],
                       check=True, capture_output=True, text=True)
        with open(out) as f:
            cli = list(csv.DictReader(f))
        self.assertEqual([float(x["error"]) for x in cli], [x["error"] for x in four["rows"]])

    def test_bad_arguments_raise_with_the_cli_messages(self):
        base = dict(scene="default", size=(32, 18), frames=1, quiet=True)
        cases = [
            (dict(sweep={"ssao.samples": [4, 8]}, metric="mse"), ValueError, "--metric: expected flip, rms, psnr, ssim or temporal"),
            (dict(sweep={"ssao.samples": [4, 8]}, buffer="shade"), ValueError, "--buffer: expected final, lbuffer"),
            (dict(sweep={"ssao.samples": [4, 8]}, mask="edges"), ValueError, "--mask: expected shadow_edges"),
            (dict(sweep={"ssao.samples": []}), ValueError, "sweep['ssao.samples'] has no values"),
            (dict(sweep={"ssao.samples": "4,8"}), ValueError, "must be a list of values"),
            (dict(sweep={"ssao.samples": ["many"]}), dw.KnobError, "ssao.samples"),
            (dict(sweep={"ssao.no_such": [1]}), dw.KnobError, "ssao.no_such"),
            (dict(settings={"ssao.samples": "many"}), dw.KnobError, "ssao.samples"),
            (dict(), ValueError, "tradeoff needs axes"),
            (dict(knobs="speed"), ValueError, "--knobs: the only set is speed/quality"),
            (dict(knobs="speed/quality", sweep={"ssao.samples": [4]}), ValueError, "sweeps its own axes"),
            (dict(sweep={"ssao.samples": [4, 8]}, frames=0), ValueError, "tradeoff: frames must be an integer between 1 and 100000 (as tradeoff --frames)"),
            (dict(sweep={"ssao.samples": [4, 8]}, resamples=5), ValueError, "tradeoff: resamples must be an integer between 100 and 1000000"),
            (dict(sweep={"ssao.samples": [4, 8]}, ao_rays=0), ValueError, "tradeoff: ao_rays must be an integer between 1 and 1048576"),
            (dict(sweep={"ssao.samples": [4, 8]}, ref_spp=0), ValueError, "tradeoff: ref_spp must be an integer between 1 and 65536"),
            (dict(sweep={"ssao.samples": [4, 8]}, ref_spp=10**9), ValueError, "tradeoff: ref_spp must be an integer between 1 and 65536"),
            (dict(sweep={"ssao.samples": [4, 8]}, ref_filter="gauss"), ValueError, "--ref-filter: expected box or tent, got 'gauss'"),
            (dict(sweep={"ssao.samples": [4, 8]}, size=(0, 18)), ValueError, "tradeoff: size width must be an integer between 1 and 16384"),
            (dict(sweep={"ssao.samples": [4, 8]}, shard="3/2"), ValueError, "--shard expects i/n"),
            (dict(sweep={"ssao.samples": [4, 8]}, exclude=["ssao.samples=4,8"]), ValueError,
             "the sweep is empty after --exclude"),
            (dict(sweep={"ssao.samples": [4, 8]}, exclude=["ssao.radius=1"]), ValueError,
             "'ssao.radius' is not an axis of this sweep"),
            (dict(sweep={"ssao.samples": [4, 8]}, against="ssao.no_such=1"), ValueError, "--against: expected"),
            (dict(sweep={"ssao.samples": [4, 8]}, presets=["NO_SUCH"]), ValueError, "NO_SUCH"),
            (dict(sweep={"ssao.samples": [4, 8]}, plot="p.jpg"), ValueError, "--plot writes a PNG"),
            (dict(sweep={"ssao.samples": [4, 8]}, csv="same.csv", json="same.csv"), ValueError, "same.csv"),
            (dict(sweep={"ssao.samples": [4, 8]}, record="a.json", json="b.json"), ValueError, "name two files"),
            (dict(sweep={"ssao.samples": [4, 8]}, record=""), ValueError, "tradeoff: record"),
            (dict(sweep={"ssao.samples": [4, 8]}, progress=3), ValueError, "progress must be a callable"),
            (dict(sweep={"ssao.samples": [4, 8]}, budget_ms=0), ValueError,
             "--budget-ms must be a number above 0 and at most 1000000000 (GPU milliseconds), got '0'"),
            (dict(sweep={"ssao.samples": [4, 8]}, budget_ms=float("nan")), ValueError, "--budget-ms must be a number"),
            # Above the CLI's range (OptionLimits' kBudgetMs): refused as tradeoff --budget-ms 2e9 is, in its words.
            (dict(sweep={"ssao.samples": [4, 8]}, budget_ms=2e9), ValueError,
             "--budget-ms must be a number above 0 and at most 1000000000 (GPU milliseconds), got '2000000000'"),
            (dict(sweep={"ssao.samples": [4, 8]}, cost="fragments", budget=2e18), ValueError,
             "--budget must be a number above 0 and at most 1e+18 (the --cost counter's unit), got '2e+18'"),
            (dict(sweep={"ssao.samples": [4, 8]}, time="ao+ao"), ValueError, "'ao' is named twice"),
            (dict(sweep={"ssao.samples": [4, 8]}, cost="pixels"), ValueError, "--cost: expected one of gpu_ms, fragments"),
            (dict(sweep={"ssao.samples": [4, 8]}, cost="fragments", budget=1000, budget_ms=5), ValueError,
             "--budget-ms and --budget: give one"),
            (dict(sweep={"ssao.samples": [4, 8]}, budget=1000), ValueError, "--budget bounds a counter"),
            (dict(sweep={"ssao.samples": [4, 8]}, cost="fragments", budget=0), ValueError, "--budget must be a number above 0"),
            (dict(sweep={"ssao.samples": [4, 8]}, scene=os.path.join(self.tmp.name, "missing.gltf")), dw.Error,
             "missing.gltf"),
        ]
        for kwargs, error, message in cases:
            with self.assertRaises(error, msg=str(kwargs)) as e:
                dw.tradeoff(**dict(base, **kwargs))
            self.assertIn(message, str(e.exception), kwargs)
        # A name the pipeline has no pass of is refused before the timed rounds: ValueError naming --time,
        # as every other bad argument (alone or as a term of a sum).
        for time, says in (("bogus", "--time bogus: the pipeline has no pass of that name"),
                           ("lighting+bogus", "--time lighting+bogus: the pipeline has no pass 'bogus'")):
            with self.assertRaises(ValueError) as e:
                dw.tradeoff(**dict(base, sweep={"ssao.samples": [4]}, time=time, against="ssao.samples=8"))
            self.assertIn(says, str(e.exception))
        # A budget is a number: True is not 1 ms, nor "5" 5 ms.
        for kwargs in (dict(budget_ms=True), dict(budget_ms="5"), dict(cost="fragments", budget=True)):
            with self.assertRaises(TypeError, msg=str(kwargs)) as e:
                dw.tradeoff(**dict(base, sweep={"ssao.samples": [4, 8]}, **kwargs))
            self.assertIn("must be a number", str(e.exception))

    def test_a_sum_of_passes_and_a_budget_pick(self):
        """time= takes a sum (the rows carry it with an interval), budget_ms= returns the pick, and every row
        says its place on the front (issue 34)."""
        r = dw.tradeoff(**dict(KEYWORDS, time="lighting+ao", budget_ms=1000.0))
        rows = r["rows"]
        for row in rows:
            self.assertEqual(row["time"], "lighting+ao")
            self.assertLessEqual(row["time_ms_lo"], row["time_ms"])
            self.assertIn(row["front"], ("pareto", "indistinguishable", "dominated"))
            self.assertEqual(row["pareto"], row["front"] == "pareto")
            for point, axes in row["tied_with"]:
                self.assertIn(axes, ("time", "error", "both"))
        self.assertIn("Holm", r["front_rule"])
        pick = r["pick"]
        self.assertEqual(pick["budget_ms"], 1000.0)
        self.assertIn(pick["point"], [row["point"] for row in rows])
        self.assertEqual(pick["row"]["pick"], "pick")
        self.assertTrue(pick["lines"][0].startswith("pick: point "), pick["lines"])
        # The least error among the points that fit (here all of them).
        self.assertEqual(pick["row"]["error"], min(row["error"] for row in rows))

    def test_studies_are_one_front_and_one_record(self):
        """studies= is repeated --study (issue 34 part 5): several grids in one run, the column study, one front
        across every point, one record; the same errors as the CLI's --study; bad studies raise ValueError."""
        path = os.path.join(self.tmp.name, "studies.json")
        common = dict(scene="default", size=(48, 27), metric="rms", buffer="ao", frames=2, warmup=0, resamples=100,
                      quiet=True)
        r = dw.tradeoff(studies={"ssao": {"ao.method": "ssao", "ssao.samples": [4, 8]},
                                 "gtao": {"ao.method": "gtao", "gtao.slices": [1, 2]}}, record=path, **common)
        rows = r["rows"]
        self.assertEqual([row["study"] for row in rows], ["ssao", "ssao", "gtao", "gtao"])
        self.assertEqual([row["ao.method"] for row in rows], ["ssao", "ssao", "gtao", "gtao"])
        self.assertGreaterEqual(sum(row["front"] == "pareto" for row in rows), 1)
        for row in rows:
            self.assertIn(row["front"], ("pareto", "indistinguishable", "dominated"))
        with open(path) as f:
            record = json.load(f)
        self.assertEqual(len(record["grid"]["points"]), 4)
        out = os.path.join(self.tmp.name, "studies-cli.csv")
        subprocess.run([BINARY, "tradeoff", "--scene", "default", "--size", "48x27", "--metric", "rms", "--buffer", "ao",
                        "--frames", "2", "--warmup", "0", "--resamples", "100", "--quiet", "--plot", "none",
                        "--study", "ssao:ao.method=ssao:ssao.samples=4,8", "--study", "gtao:ao.method=gtao:gtao.slices=1,2",
                        "--csv", out, "--json", os.path.join(self.tmp.name, "studies-cli.json")],
                       check=True, capture_output=True, text=True)
        with open(out) as f:
            cli = list(csv.DictReader(f))
        self.assertEqual([c["study"] for c in cli], [row["study"] for row in rows])
        for c, row in zip(cli, rows):
            self.assertAlmostEqual(float(c["error"]), row["error"], delta=1e-9 * max(1.0, abs(row["error"])))
        for studies, says in [([{}], "an empty study"),
                              ([{"ssao.samples": [4, 8]}, {"ssao.samples": [8]}], "is given twice"),
                              ([{"ssao.nonsense": 1}], "unknown knob 'ssao.nonsense'"),
                              ("ssao", "studies: expected a list")]:
            with self.assertRaises(ValueError) as caught:
                dw.tradeoff(studies=studies, **common)
            self.assertIn(says, str(caught.exception))
        with self.assertRaises(ValueError) as caught:
            dw.tradeoff(studies=[{"ao.method": "ssao"}], sweep={"ssao.samples": [4, 8]}, **common)
        self.assertIn("--study makes its own grids", str(caught.exception))

    def test_record_keyword_writes_the_record(self):
        # record= is the CLI's --record (json= its older name): the experiment record, one format.
        path = os.path.join(self.tmp.name, "kw-tradeoff.json")
        dw.tradeoff(scene="default", size=(32, 18), sweep={"ssao.samples": [4, 8]}, against="ssao.samples=16",
                    metric="rms", buffer="ao", frames=1, warmup=0, resamples=200, quiet=True, record=path)
        with open(path) as f:
            record = json.load(f)
        self.assertEqual(record["command"], "tradeoff")
        self.assertEqual(len(record["results"]["rows"]), 2)
        path = os.path.join(self.tmp.name, "kw-bench.json")
        dw.bench(scene="default", sizes=[(32, 18)], sweep={"ssao.samples": [4, 8]}, frames=1, warmup=0,
                 resamples=200, record=path, json=path)
        with open(path) as f:
            record = json.load(f)
        self.assertEqual(record["command"], "bench")
        self.assertEqual(len(record["results"]["configs"]), 2)
        with self.assertRaises(ValueError) as e:
            dw.bench(scene="default", sizes=[(32, 18)], frames=1, record=path, json=path + ".other")
        self.assertIn("name two files", str(e.exception))

    def test_progress_that_raises_stops_the_run(self):
        def stop(line):
            raise KeyError("stop at " + line)
        with self.assertRaises(KeyError) as e:
            dw.tradeoff(scene="default", size=(32, 18), sweep={"ssao.samples": [4, 8]}, frames=1, progress=stop)
        self.assertIn("tradeoff: setting up", str(e.exception))

    def test_a_second_thread_raises(self):
        caught = []

        def other():
            try:
                dw.tradeoff(scene="default", size=(32, 18), sweep={"ssao.samples": [4]}, frames=1, quiet=True)
            except Exception as e:  # noqa: BLE001 - the test looks at what came
                caught.append(e)
        t = threading.Thread(target=other)
        t.start()
        t.join()
        self.assertEqual(len(caught), 1)
        self.assertIsInstance(caught[0], dw.ThreadError)


if __name__ == "__main__":
    unittest.main()
