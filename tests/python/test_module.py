"""The Python module deferred_workbench (issue 24), run by ctest as
`python3 -m unittest` with PYTHONPATH=<build>/python and DW_WORKBENCH_BINARY
naming the CLI. Every named output the default pipeline produces comes back
with its shape and dtype and equals `render --buffer` of the same
configuration bit for bit; a knob set from Python is what --dump-knobs shows;
bad input raises (KnobError is a ValueError), never crashes."""
import concurrent.futures
import hashlib
import json
import os
import subprocess
import tempfile
import threading
import unittest
import warnings

import numpy as np

import deferred_workbench as dw

BINARY = os.environ["DW_WORKBENCH_BINARY"]
SIMPLE_SKIN = "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf"
SIZE = (96, 54)
# Kinds read back raw (float32): the channels each holds (Color outputs that
# are not 8-bit display images are raw floats too).
RAW_CHANNELS = {"depth": (1,), "normal-kl": (2,), "hdr": (3, 4), "vector": (3, 4), "scalar": (1, 2, 3, 4),
                "count": (1, 2, 3, 4), "color": (3, 4)}


def cli_render(tmp, buffer, out_name, settings=(), extra=()):
    out = os.path.join(tmp, out_name)
    args = [BINARY, "render", "--size", "%dx%d" % SIZE, "--buffer", buffer, "--out", out]
    for s in settings:
        args += ["--set", s]
    args += list(extra)
    subprocess.run(args, check=True, capture_output=True, text=True)
    return out


class SessionTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.session = dw.Session(scene="default", size=SIZE)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_final_and_lbuffer_equal_the_cli_bit_for_bit(self):
        # A fresh session: its first frame is the CLI's only frame.
        s = dw.Session(scene="default", size=SIZE)
        final = s.render("final")
        self.assertEqual(final.dtype, np.uint8)
        self.assertEqual(final.shape[:2], (SIZE[1], SIZE[0]))
        png = dw.load_image(cli_render(self.tmp.name, "final", "final.png"))
        self.assertEqual(png.dtype, np.uint8)
        np.testing.assert_array_equal(final, png)
        self.assertGreater(int(final.max()), 0)

        lbuffer = s.render("lbuffer")
        self.assertEqual(lbuffer.dtype, np.float32)
        exr = dw.load_image(cli_render(self.tmp.name, "lbuffer", "lbuffer.exr"))
        self.assertEqual(exr.dtype, np.float32)
        self.assertEqual(lbuffer.shape, exr.shape)
        self.assertTrue(np.array_equal(lbuffer, exr, equal_nan=True))
        self.assertGreater(float(np.nanmax(lbuffer[..., :3])), 0.0)

    def test_every_produced_output_has_its_shape_and_dtype_and_equals_the_cli(self):
        # A fresh session; each buffer rendered as `render --buffer NAME` renders it
        # (a frame that asks for it), read back as the CLI writes it.
        s = dw.Session(scene="default", size=SIZE)
        details = {b["name"]: b for b in s.buffers(details=True)}
        self.assertEqual(list(details), s.buffers())
        listed = subprocess.run([BINARY, "list", "buffers"], check=True, capture_output=True, text=True).stdout
        self.assertEqual([line.split()[0] for line in listed.splitlines() if line.strip()], s.buffers())
        produced = {}
        for name, info in details.items():
            if info["pass"] == "reference":
                continue  # the CPU reference's outputs: test_reference_outputs_equal_the_cli_reference
            try:
                image = s.render(name)
            except dw.Error as e:
                # Not produced under the default knobs: the pipeline says why.
                self.assertTrue(any(w in str(e) for w in ("not produced", "written only", "is empty")), str(e))
                continue
            produced[name] = image
            self.assertEqual(image.ndim, 3, name)
            if image.dtype == np.uint8:
                self.assertEqual(info["kind"], "color", name)
                self.assertEqual(image.shape, (SIZE[1], SIZE[0], 4), name)
            else:
                self.assertEqual(image.dtype, np.float32, name)
                self.assertIn(image.shape[2], RAW_CHANNELS[info["kind"]], name)
        full = ["gbuffer.albedo", "gbuffer.normal", "gbuffer.depth", "gbuffer.view_position", "ao.filtered",
                "lbuffer", "lbuffer.depth", "lighting.overlap", "tonemap.result", "final"]
        for name in full:
            self.assertIn(name, produced)
            self.assertEqual(produced[name].shape[:2], (SIZE[1], SIZE[0]), name)
        self.assertEqual(produced["gbuffer.depth"].shape[2], 1)
        self.assertEqual(produced["gbuffer.normal"].shape[2], 2)
        self.assertEqual(produced["ao.raw"].shape[:2], (SIZE[1] // 2, SIZE[0] // 2))  # ssao.resolution = half
        for name in ("final", "tonemap.result", "fxaa.result"):
            self.assertEqual(produced[name].dtype, np.uint8, name)

        # Each one equals `render --buffer NAME` (.png for uint8, .exr for float32) bit for bit.
        def cli(name):
            ext = ".png" if produced[name].dtype == np.uint8 else ".exr"
            return name, dw.load_image(cli_render(self.tmp.name, name, "every-" + name + ext))

        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            files = dict(pool.map(cli, produced))
        for name, image in produced.items():
            self.assertEqual(image.dtype, files[name].dtype, name)
            self.assertEqual(image.shape, files[name].shape, name)
            self.assertTrue(np.array_equal(image, files[name], equal_nan=True), name)

    def test_knob_set_from_python_is_what_dump_knobs_shows(self):
        s = dw.Session(scene="default", size=SIZE, settings={"ssao.samples": 12})
        s.set("tonemap.operator", "aces")
        s.set("shadows.enabled", False)
        s.set("ssao.radius", 0.75)
        self.assertEqual(s.get("ssao.samples"), 12)
        self.assertEqual(s.get("tonemap.operator"), "aces")
        self.assertIs(s.get("shadows.enabled"), False)
        self.assertAlmostEqual(s.get("ssao.radius"), 0.75)
        dump = os.path.join(self.tmp.name, "knobs.txt")
        cli_render(self.tmp.name, "final", "knobs.png",
                   settings=["ssao.samples=12", "tonemap.operator=aces", "shadows.enabled=false", "ssao.radius=0.75"],
                   extra=["--dump-knobs", dump])
        with open(dump) as f:
            cli = dict(line.strip().split("=", 1) for line in f if "=" in line and not line.startswith("#"))
        self.assertEqual(s.knobs(text=True), cli)
        # and the module's own dump is the CLI's, line for line
        mine = os.path.join(self.tmp.name, "mine.txt")
        s.dump_knobs(mine)
        with open(mine) as a, open(dump) as b:
            self.assertEqual(a.read().splitlines()[1:], b.read().splitlines()[1:])
        # the values typed: bool, int, float, enum choice
        knobs = s.knobs()
        self.assertIsInstance(knobs["shadows.enabled"], bool)
        self.assertIsInstance(knobs["ssao.samples"], int)
        self.assertIsInstance(knobs["ssao.radius"], float)
        self.assertEqual(knobs["tonemap.operator"], "aces")

    def test_bad_knobs_raise_knob_error_with_the_registry_message(self):
        s = self.session
        with self.assertRaises(dw.KnobError) as bad_name:
            s.set("ssao.no_such_knob", 1)
        self.assertIsInstance(bad_name.exception, ValueError)
        self.assertIn("ssao.no_such_knob", str(bad_name.exception))
        with self.assertRaises(dw.KnobError) as bad_value:
            s.set("tonemap.operator", "sepia")
        self.assertIn("sepia", str(bad_value.exception))
        self.assertIn("reinhard", str(bad_value.exception))  # the accepted values are named
        with self.assertRaises(ValueError):
            s.set("ssao.samples", "many")
        with self.assertRaises(dw.KnobError):
            s.get("nope")
        with self.assertRaises(dw.KnobError):
            dw.Session(scene="default", size=SIZE, settings={"ssao.samples": "lots"})
        # the registry's message is the CLI's
        cli = subprocess.run([BINARY, "render", "--size", "8x8", "--set", "tonemap.operator=sepia", "--out",
                              os.path.join(self.tmp.name, "x.png")], capture_output=True, text=True)
        self.assertNotEqual(cli.returncode, 0)
        self.assertIn(str(bad_value.exception), cli.stderr)
        self.assertEqual(s.get("tonemap.operator"), "reinhard")  # nothing changed

    def test_an_old_knob_name_is_the_knob_it_became(self):
        # KnobRegistry::addAlias: ssao.enabled is now ao.enabled; set and get take either (with a warning).
        s = dw.Session(scene="default", size=(16, 9))
        s.set("ssao.enabled", False)
        self.assertIs(s.get("ao.enabled"), False)
        self.assertIs(s.get("ssao.enabled"), False)
        s.set("ao.enabled", True)
        self.assertIs(s.get("ssao.enabled"), True)
        self.assertNotIn("ssao.enabled", s.knobs())

    def test_bad_scene_buffer_and_size_raise(self):
        bad = os.path.join(self.tmp.name, "broken.json")
        with open(bad, "w") as f:
            f.write("{ not json")
        with self.assertRaises(dw.Error) as e:
            dw.Session(scene=bad, size=SIZE)
        self.assertIn("broken.json", str(e.exception))
        with self.assertRaises(dw.Error):
            dw.Session(scene=os.path.join(self.tmp.name, "missing.gltf"), size=SIZE)
        with self.assertRaises(dw.Error):
            dw.Session(scene="nowhere", size=SIZE)
        with self.assertRaises(ValueError):
            dw.Session(scene="default", size=(0, 10))
        with self.assertRaises(dw.Error):
            dw.Session(scene="default", size=SIZE, preset="no-such-preset")
        with self.assertRaises(ValueError):
            self.session.render("no.such.buffer")
        with self.assertRaises(ValueError):
            self.session.render("final", frames=0)
        with self.assertRaises(ValueError):
            self.session.render("final", frames=100001)  # render --frames' range, 1..100000
        with self.assertRaises(ValueError):
            dw.Session(scene="default", size=SIZE, preset=["Low", 3])
        with self.assertRaises(dw.Error):
            dw.load_image(os.path.join(self.tmp.name, "absent.png"))
        with self.assertRaises(dw.Error):
            dw.compare(np.zeros((4, 4, 3), np.float32), np.zeros((5, 4, 3), np.float32))

    def test_presets_apply_in_order_as_repeated_preset(self):
        # Low sets the SSAO knobs, GTAO high only the ao and gtao groups: both
        # apply, the later one winning where they meet (ao.method).
        both = dw.Session(scene="default", size=SIZE, preset=["Low", "GTAO high"])
        low = dw.Session(scene="default", size=SIZE, preset="Low")
        self.assertEqual(both.get("ao.method"), "gtao")
        self.assertEqual(both.get("shadows.map_size"), low.get("shadows.map_size"))
        self.assertEqual(both.get("ssao.samples"), low.get("ssao.samples"))
        self.assertEqual(low.get("shadows.map_size"), 512)
        # Where two presets set the same knob, the later wins.
        self.assertEqual(dw.Session(scene="default", size=SIZE, preset=("Low", "High")).get("shadows.map_size"), 2048)
        self.assertEqual(dw.Session(scene="default", size=SIZE, preset=["High", "Low"]).get("shadows.map_size"), 512)

    def test_a_second_thread_raises(self):
        s = self.session
        caught = []

        calls = [lambda: s.render("final"), lambda: s.get("ssao.samples"), lambda: s.set("ssao.samples", 8),
                 lambda: s.knobs(), lambda: s.buffers()]

        def use():
            for call in calls:
                try:
                    call()
                except dw.ThreadError as e:
                    caught.append(str(e))

        t = threading.Thread(target=use)
        t.start()
        t.join()
        self.assertEqual(len(caught), len(calls))
        self.assertIn("thread", caught[0])
        self.assertEqual(s.render("final").shape, (SIZE[1], SIZE[0], 4))  # still usable here

    def test_timings_probe_and_compare(self):
        s = self.session
        s.render("final", frames=3, warmup=1)
        rows = s.timings()
        self.assertEqual(rows[-1]["kind"], "total")
        self.assertEqual(rows[-1]["gpu_ms"]["count"], 3)
        passes = [r for r in rows if r["kind"] == "pass"]
        self.assertTrue(any(r["name"] == "geometry" and r["ran"] for r in passes))
        for r in passes:
            if r["ran"]:
                self.assertEqual(r["cpu_ms"]["count"], 3, r["name"])
                self.assertLessEqual(r["cpu_ms"]["min"], r["cpu_ms"]["median"])
        p = s.probe(SIZE[0] // 2, SIZE[1] // 2)
        self.assertTrue(p["inside"])
        self.assertIn("lbuffer", p["values"])
        lb = s.render("lbuffer")
        np.testing.assert_allclose(p["values"]["lbuffer"]["raw"][:3], lb[SIZE[1] // 2, SIZE[0] // 2, :3], rtol=0,
                                   atol=0)
        with self.assertRaises(ValueError):
            s.probe(-1, 0)

        a = np.zeros((16, 16, 3), np.float32)
        b = a.copy()
        b[3, 5, 1] = 0.5
        r = dw.compare(a, b, maps=True)
        self.assertAlmostEqual(r["max"], 0.5)
        self.assertEqual(r["max_pixel"], (5, 3))
        self.assertEqual(r["max_channel"], 1)
        self.assertEqual(r["fail_count"], 1)
        self.assertEqual(r["maps"]["difference"].shape, (16, 16, 3))
        self.assertAlmostEqual(float(r["maps"]["difference"][3, 5, 1]), 0.5)
        self.assertEqual(dw.compare(a, a)["fail_count"], 0)

    def test_reference_ao_of_the_view(self):
        s = dw.Session(scene="default", size=(32, 18))
        ao, stats = s.reference("ao", ao_rays=8, cache=False, stats=True)
        self.assertEqual(ao.shape, (18, 32, 1))
        self.assertEqual(ao.dtype, np.float32)
        self.assertTrue(np.all((ao >= 0) & (ao <= 1)))
        self.assertLess(float(ao.min()), 1.0)  # something is occluded
        self.assertEqual(stats["primary_rays"], 32 * 18)
        with self.assertRaises(ValueError):
            s.reference("nope")

    def test_reference_samples_per_pixel(self):
        s = dw.Session(scene="default", size=(32, 18))
        one = s.reference("lbuffer", ao_rays=2, cache=False)
        area, stats = s.reference("lbuffer", ao_rays=2, cache=False, spp=4, stats=True)
        self.assertEqual(stats["primary_rays"], 32 * 18 * 4)
        self.assertEqual(stats["pixel_samples"], 4)
        self.assertFalse(np.array_equal(one, area))
        err = s.reference("spp_error", ao_rays=2, cache=False, spp=4, filter="tent")
        self.assertEqual(err.shape, (18, 32, 1))
        self.assertGreater(float(err.max()), 0.0)
        with self.assertRaisesRegex(ValueError, "spp"):
            s.reference("lbuffer", spp=0)
        with self.assertRaisesRegex(ValueError, "expected box or tent"):
            s.reference("lbuffer", spp=4, filter="gauss")

    def test_bench_grid_records_and_csv(self):
        csv = os.path.join(self.tmp.name, "bench.csv")
        path = os.path.join(self.tmp.name, "bench.json")
        r = dw.bench(scene="default", sizes=[(64, 36)], sweep={"ssao.samples": [4, 16]}, frames=2, warmup=1,
                     csv=csv, json=path)
        # The record bench --json writes, as Python objects, and the file holds the same.
        with open(path) as f:
            self.assertEqual(json.load(f), r)
        self.assertEqual((r["format"], r["version"], r["command"]), ("deferred-workbench record", 2, "bench"))
        self.assertEqual(r["grid"]["sizes"], ["64x36"])
        self.assertEqual(r["seeds"]["lights"], "1")
        self.assertIn("renderer", r["gl"])
        configs = r["results"]["configs"]
        self.assertEqual([c["knobs"] for c in configs], [{"ssao.samples": "4"}, {"ssao.samples": "16"}])
        self.assertEqual([c["size"] for c in configs], ["64x36", "64x36"])
        self.assertIn("4 samples", configs[0]["stats"]["ao"])
        self.assertIn("16 samples", configs[1]["stats"]["ao"])
        for c in configs:
            self.assertEqual([x["sample"] for x in c["samples"]], [0, 1])
            self.assertEqual(c["series"]["frame"]["gpu_ms"]["frames"], 2)
        self.assertEqual(configs[0]["ratio"], 1.0)  # the baseline, ssao.samples=4
        self.assertEqual(len(configs[1]["ci95"]), 2)
        self.assertEqual(r["results"]["settings"]["frames"], "2")
        self.assertIn("gl_renderer", r["results"]["machine"])
        with open(csv) as f:
            lines = f.read().splitlines()
        rows = sum(len(x["gpu_ms"]) for c in configs for x in c["samples"])
        self.assertEqual(len(lines), rows + 1)
        header = lines[0].split(",")
        first = dict(zip(header, lines[1].split(",")))
        self.assertAlmostEqual(float(first["gpu_ms"]), configs[0]["samples"][0]["gpu_ms"][first["pass"]], places=3)
        # The cost counters: each sample's per series (the CSV's columns), the same in both counted frames.
        self.assertEqual(int(first["fragments"]), configs[0]["samples"][0]["counters"][first["pass"]]["fragments"])
        for c in configs:
            self.assertEqual(c["samples"][0]["counters"], c["samples"][1]["counters"])
            self.assertGreater(c["samples"][0]["counters"]["frame"]["fragments"], 0)
        self.assertEqual(r["results"]["counters_mismatch"], "")
        orbit = dw.bench(scene="default", sizes=[(32, 18)], frames=2, warmup=0, orbit=2)
        self.assertEqual(orbit["camera_path"], {"mode": "orbit", "orbit_poses": 2})
        self.assertEqual(orbit["results"]["settings"]["camera"], "orbit 2")
        # An empty or non-list axis and an impossible light count raise (an empty axis crashed once).
        for bad in ({"sweep": {"ssao.samples": []}}, {"sweep": {"ssao.samples": [4], "ssao.radius": []}},
                    {"sweep": {"ssao.samples": "4,8"}}, {"sweep": {"ssao.samples": 4}}, {"lights": [10**9]}):
            with self.assertRaises(ValueError, msg=str(bad)):
                dw.bench(scene="default", sizes=[(32, 18)], frames=1, **bad)
        with self.assertRaises(dw.KnobError):
            dw.bench(sweep={"ssao.samples": ["many"]}, frames=1)
        with self.assertRaises(dw.KnobError):
            dw.bench(sweep={"ssao.no_such": [1]}, frames=1)

    def test_an_aov_frame_over_the_cost_limit_warns_before_it_renders(self):
        # Issue 22: the courtyard at aov.radius 20 is over AovCostEstimate's limits; at 1 it is not.
        s = dw.Session(scene="default", size=(32, 18),
                       settings={"ao.method": "aov", "aov.resolution": "quarter", "aov.radius": 20})
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            s.render()
        lines = [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]
        self.assertTrue(any(l.startswith("aov: about ") and "a frame on llvmpipe" in l for l in lines), lines)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            with self.assertRaises(RuntimeWarning):
                s.render()
            s.set("aov.radius", 1)
            s.render()  # under the limit: no warning (it would raise here)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            dw.bench(scene="default", sizes=[(32, 18)], sweep={"aov.radius": [1, 20]}, frames=1, warmup=0,
                     settings={"ao.method": "aov", "aov.resolution": "quarter"})
        lines = [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]
        self.assertEqual(len(lines), 1, lines)
        self.assertIn("bench: warning: configuration 1 (32x18): aov: about ", lines[0])

    def test_render_warns_when_transparency_loses_fragments(self):
        # Issue 32: the line `render` prints when the oit pass lost fragments
        # (the 4-sample A-buffer on the glass scene), as a RuntimeWarning
        # whose count is what oit.overflow sums to; the exact list says nothing.
        s = dw.Session(scene="glass", size=(160, 90), settings={"oit.method": "abuffer", "oit.samples": 4})
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            overflow = s.render("oit.overflow")
        lines = [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            counts = s.render("oit.sample_count")
        lost = int(overflow.astype("int64").sum())
        self.assertGreater(lost, 0)
        self.assertEqual([l for l in lines if l.startswith("oit: ")],
                         ["oit: lost %d of %d transparent fragments this frame (abuffer keeps 4 per pixel "
                          "(oit.samples = 4), the first to arrive); oit.overflow shows where"
                          % (lost, int(counts.astype("int64").sum()))], lines)
        s.set("oit.method", "linked_list")
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            s.render()  # nothing lost: no warning (it would raise here)
        # bench says it too, once a configuration, with how many counted frames lost some.
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            dw.bench(scene="glass", sizes=[(32, 18)], settings={"oit.method": "abuffer", "oit.samples": 4},
                     frames=2, warmup=0, resamples=100)
        bench_lines = [str(w.message) for w in caught if "oit: lost" in str(w.message)]
        self.assertEqual(len(bench_lines), 1, [str(w.message) for w in caught])
        self.assertTrue(bench_lines[0].startswith("bench: warning: configuration 0 ("), bench_lines[0])
        self.assertIn("(in 2 of 2 counted frames; the first such frame's figures)", bench_lines[0])
        # A blended pane of emission 1e30: the loader's clamp is warned about
        # when the session opens, and the L-buffer is finite (0.5 x 65000 + ...).
        path = os.path.join(tempfile.mkdtemp(), "hot.json")
        with open(path, "w") as f:
            f.write('{"camera": {"pos": [0, 0, 10], "look-at": [0, 0, 0]}, "objects": [{"shape": "plane", '
                    '"size": [40, 0, 40], "rotate": [90, 0, 0], "material": {"diffuse": [0.5, 0.5, 0.5], '
                    '"emissive": [1e30, 1e30, 1e30], "opacity": 0.5}}]}')
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            hot = dw.Session(scene=path, size=(32, 18))
        lines = [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]
        self.assertTrue(any(path + ": material 'objects[0]': emissive 1e+30 is beyond 65000" in l for l in lines), lines)
        lbuffer = hot.render("lbuffer")
        self.assertTrue(np.isfinite(lbuffer).all())
        self.assertGreater(float(lbuffer[..., :3].max()), 32000.0)

    def test_render_record_replays_to_the_same_image(self):
        s = dw.Session(scene="default", size=(48, 27))
        s.set("ssao.samples", 8)
        path = os.path.join(self.tmp.name, "py-record.json")
        image = s.render("final", frames=2, warmup=1, record=path)
        with open(path) as f:
            d = json.load(f)
        self.assertEqual((d["version"], d["command"], d["size"], d["frames"], d["warmup"]), (2, "render", [48, 27], 2, 1))
        self.assertEqual(d["knobs"]["ssao.samples"], "8")
        self.assertEqual(d["results"]["image"]["sha256"], hashlib.sha256(image.tobytes()).hexdigest())
        r = subprocess.run([BINARY, "replay", path], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("image: identical", r.stdout)
        # Session.record: the last render's buffer and knobs; a set() since the
        # render is refused by name (the knobs would not be the image's).
        s.render("ao.raw")
        s.set("tonemap.key", 0.25)
        with self.assertRaises(dw.Error) as e:
            s.record(os.path.join(self.tmp.name, "py-record-2.json"))
        self.assertIn("tonemap.key", str(e.exception))
        s.render("ao.raw")
        again = s.record(os.path.join(self.tmp.name, "py-record-2.json"))
        self.assertEqual((again["buffer"], again["knobs"]["tonemap.key"]), ("ao.raw", "0.25"))
        with self.assertRaises(dw.Error):
            dw.Session(scene="default", size=(8, 8)).record(os.path.join(self.tmp.name, "none.json"))
        # An animated scene: only the first render() of a Session (frame 0, as the CLI's) is recorded; a
        # later one began at another frame index and replayed 'differs' with no input named.
        fire = dw.Session(scene="fire", size=(32, 18))
        first = os.path.join(self.tmp.name, "py-fire-1.json")
        fire.render("final", frames=6, warmup=1, record=first)
        r = subprocess.run([BINARY, "replay", first], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("image: identical", r.stdout)
        with self.assertRaises(dw.Error) as e:
            fire.render("final", frames=6, warmup=1, record=os.path.join(self.tmp.name, "py-fire-2.json"))
        self.assertIn("this render() began at frame 7", str(e.exception))
        self.assertFalse(os.path.exists(os.path.join(self.tmp.name, "py-fire-2.json")))
        fire.render("final", frames=2)
        with self.assertRaises(dw.Error) as e:
            fire.record(os.path.join(self.tmp.name, "py-fire-3.json"))
        self.assertIn("the last render() began at frame 7", str(e.exception))

    def test_reference_outputs_equal_the_cli_reference(self):
        # reference.lbuffer, reference.final and reference.ao are `reference --buffer lbuffer|final|ao`'s
        # images of the session's view bit for bit; compare.error is the reference pass's per-pixel
        # |L - L_ref| / (L_ref + 0.001) of this frame's lbuffer (L the luminance), as the workbench shows it.
        size = (48, 27)
        s = dw.Session(scene="default", size=size)
        self.assertTrue({"reference.lbuffer", "reference.final", "reference.ao", "compare.error"} <= set(s.buffers()))
        files = {}
        for name in ("lbuffer", "final", "ao"):
            out = os.path.join(self.tmp.name, "cli-reference-%s.exr" % name)
            subprocess.run([BINARY, "reference", "--size", "%dx%d" % size, "--buffer", name, "--ao-rays", "8",
                            "--seed", "3", "--no-cache", "--quiet", "--out", out], check=True, capture_output=True)
            files[name] = dw.load_image(out)
        seen = []
        for name in ("lbuffer", "final", "ao"):
            image = s.render("reference." + name, ao_rays=8, seed=3, threads=1, cache=False, progress=seen.append)
            self.assertEqual(image.dtype, np.float32, name)
            self.assertEqual(image.shape, files[name].shape, name)
            self.assertEqual(image.shape[:2], (size[1], size[0]), name)
            self.assertTrue(np.array_equal(image, files[name], equal_nan=True), name)
        self.assertEqual(seen[-1], 1.0)
        self.assertTrue(all(0.0 <= f <= 1.0 for f in seen), seen)
        self.assertLess(float(files["ao"].min()), 1.0)  # something is occluded

        error = s.render("compare.error", ao_rays=8, seed=3, cache=False)
        self.assertEqual((error.dtype, error.shape), (np.float32, (size[1], size[0], 1)))

        def luminance(p):
            p = p.astype(np.float64)
            return (0.2126 * p[..., 0] + 0.7152 * p[..., 1] + 0.0722 * p[..., 2]).astype(np.float32).astype(np.float64)

        frame, ref = luminance(s.render("lbuffer")), luminance(files["lbuffer"])
        expected = (np.abs(frame - ref) / (ref + 1e-3)).astype(np.float32)
        self.assertTrue(np.array_equal(error[..., 0], expected))
        self.assertGreater(float(error.max()), 0.0)

        # A knob of the model changes the reference (the view's, not an earlier one's).
        s.set("ao.enabled", False)
        self.assertFalse(np.array_equal(s.render("reference.lbuffer", ao_rays=8, seed=3, cache=False), files["lbuffer"]))
        s.set("ao.enabled", True)

        # An exception in progress (or Ctrl-C) stops the trace and is raised; the session stays usable.
        class Stop(Exception):
            pass

        def stop(fraction):
            raise Stop()

        with self.assertRaises(Stop):
            s.render("reference.ao", ao_rays=4096, cache=False, progress=stop)
        with self.assertRaises(Stop):
            s.reference("ao", ao_rays=4096, cache=False, progress=stop)
        self.assertEqual(s.render("final").shape, (size[1], size[0], 4))
        # A record holds no ao_rays or seed, so replay could not trace the reference again: refused, by name.
        with self.assertRaises(ValueError) as e:
            s.render("reference.ao", ao_rays=8, record=os.path.join(self.tmp.name, "ref-record.json"))
        self.assertIn("reference.ao", str(e.exception))
        s.render("reference.ao", ao_rays=8, seed=3)
        with self.assertRaises(dw.Error) as e:
            s.record(os.path.join(self.tmp.name, "ref-record.json"))
        self.assertIn("reference.ao", str(e.exception))

    def test_reference_outputs_equal_render_buffer_of_the_cli(self):
        # Session.render("reference.ao" / "compare.error") and `render --buffer` of the same view and
        # reference options trace the same reference (renderer/reference/ViewReference) and hand it
        # to the reference pass the same way: bit for bit.
        size = (32, 18)
        s = dw.Session(scene="default", size=size)
        images = {}
        for name in ("reference.ao", "compare.error"):
            out = os.path.join(self.tmp.name, "cli-%s.exr" % name)
            r = subprocess.run([BINARY, "render", "--size", "%dx%d" % size, "--buffer", name, "--ao-rays", "4",
                                "--seed", "2", "--no-cache", "--out", out], capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            cli = dw.load_image(out)
            image = s.render(name, ao_rays=4, seed=2, cache=False)
            self.assertEqual((image.dtype, image.shape), (np.float32, (size[1], size[0], 1)), name)
            self.assertTrue(np.array_equal(image, cli, equal_nan=True), name)
            images[name] = image
        self.assertLess(float(images["reference.ao"].min()), 1.0)  # something is occluded
        self.assertGreater(float(images["compare.error"].max()), 0.0)

    @unittest.skipUnless(os.path.exists(SIMPLE_SKIN), "assimp-testmodels is not installed")
    def test_scene_time_poses_the_animation_as_render_scene_time_does(self):
        # Issue 36: Session.render(scene_time=T) is `render --scene-time T` bit for bit, another
        # time another pose, and the session stays at T (scene_time) for reference().
        s = dw.Session(scene=SIMPLE_SKIN, size=SIZE)
        at0 = s.render("lbuffer", scene_time=0)
        at05 = s.render("lbuffer", scene_time=0.5)
        self.assertEqual(s.scene_time, 0.5)
        cli = dw.load_image(cli_render(self.tmp.name, "lbuffer", "skin-0.5.exr", extra=("--scene", SIMPLE_SKIN,
                                                                                         "--scene-time", "0.5")))
        np.testing.assert_array_equal(at05, cli)
        self.assertGreater(int((np.abs(at05 - at0).max(axis=2) > 1e-4).sum()), SIZE[0] * SIZE[1] // 50)
        with self.assertRaises(ValueError):
            s.render(scene_time=-1)

    def test_numeric_arguments_are_held_to_the_cli_ranges(self):
        # renderer/OptionLimits.h's ranges: outside them, however large, ValueError naming the
        # argument and the range; a value that is no integer is TypeError naming it.
        s = self.session
        s.render("final")
        small = {"sizes": [(8, 8)], "frames": 1, "warmup": 0}
        cases = [
            ("render: frames", lambda v: s.render("final", frames=v), [0, 100001, 10**12, -1], "between 1 and 100000"),
            ("render: warmup", lambda v: s.render("final", warmup=v), [-1, 100001, 2**70], "between 0 and 100000"),
            ("render: ao_rays", lambda v: s.render("final", ao_rays=v), [0, 2**20 + 1], "between 1 and 1048576"),
            ("render: threads", lambda v: s.render("final", threads=v), [-2, 4097], "between 0 and 4096"),
            ("probe: x", lambda v: s.probe(v, 0), [-1, SIZE[0], 2**40], "between 0 and %d" % (SIZE[0] - 1)),
            ("probe: y", lambda v: s.probe(0, v), [-1, SIZE[1], -2**40], "between 0 and %d" % (SIZE[1] - 1)),
            ("resize: width", lambda v: s.resize(v, 8), [0, 16385, 10**30], "between 1 and 16384"),
            ("Session: size height", lambda v: dw.Session(size=(8, v)), [0, 16385, 2**64], "between 1 and 16384"),
            ("reference: threads", lambda v: s.reference("ao", threads=v), [-2, 5000], "between 0 and 4096"),
            ("reference: ao_rays", lambda v: s.reference("ao", ao_rays=v), [0, 2**31], "between 1 and 1048576"),
            ("reference: seed", lambda v: s.reference("ao", seed=v), [-1, 2**31], "between 0 and 2147483647"),
            ("bench: frames", lambda v: dw.bench(**dict(small, frames=v)), [0, 10**12], "between 1 and 100000"),
            ("bench: warmup", lambda v: dw.bench(**dict(small, warmup=v)), [-1], "between 0 and 100000"),
            ("bench: block", lambda v: dw.bench(block=v, **small), [0, 100001], "between 1 and 100000"),
            ("bench: seed", lambda v: dw.bench(seed=v, **small), [-1, 2**31], "between 0 and 2147483647"),
            ("bench: resamples", lambda v: dw.bench(resamples=v, **small), [99, 1000001], "between 100 and 1000000"),
            ("bench: orbit", lambda v: dw.bench(orbit=v, **small), [-1, 100001], "between 0 and 100000"),
            ("bench: lights[]", lambda v: dw.bench(lights=[v], **small), [-1, 1000001], "between 0 and 1000000"),
            ("bench: sizes[] width", lambda v: dw.bench(**dict(small, sizes=[(v, 8)])), [0, 16385], "between 1 and 16384"),
            ("tradeoff: size width", lambda v: dw.tradeoff(size=(v, 8)), [0, 2**63], "between 1 and 16384"),
            ("tradeoff: ao_rays", lambda v: dw.tradeoff(ao_rays=v), [0, 2**20 + 1], "between 1 and 1048576"),
            ("tradeoff: frames", lambda v: dw.tradeoff(frames=v), [0, 10**12], "between 1 and 100000"),
            ("tradeoff: warmup", lambda v: dw.tradeoff(warmup=v), [-1], "between 0 and 100000"),
            ("tradeoff: block", lambda v: dw.tradeoff(block=v), [0], "between 1 and 100000"),
            ("tradeoff: resamples", lambda v: dw.tradeoff(resamples=v), [10], "between 100 and 1000000"),
            ("tradeoff: orbit", lambda v: dw.tradeoff(orbit=v), [-1, 100001], "between 0 and 100000"),
            ("tradeoff: plot_size width", lambda v: dw.tradeoff(plot_size=(v, 600)), [0, 49, 10**9], "between 50 and 16384"),
        ]
        for name, call, values, text in cases:
            for v in values:
                with self.assertRaises(ValueError, msg="%s=%r" % (name, v)) as e:
                    call(v)
                self.assertNotIsInstance(e.exception, dw.KnobError)
                self.assertIn(name, str(e.exception))
                self.assertIn(text, str(e.exception))
            for v in (None, 1.5, "3", True, float("nan")):
                with self.assertRaises(TypeError, msg="%s=%r" % (name, v)) as e:
                    call(v)
                self.assertIn(name, str(e.exception))
        # numpy's integers are integers; floats are thresholds: finite, at least 0 (compare --warn, --fail).
        self.assertEqual(s.render("final", frames=np.int64(2), warmup=np.uint8(0)).shape, (SIZE[1], SIZE[0], 4))
        a = np.zeros((4, 4, 3), np.float32)
        # Held to compare --warn/--fail's range: 0 to the largest 32-bit float (renderer/OptionLimits.h).
        for v in (-1e-9, float("nan"), float("inf"), 10**400, 1e39, -1):
            for key in ("warn_threshold", "fail_threshold"):
                with self.assertRaises(ValueError, msg="%s=%r" % (key, v)) as e:
                    dw.compare(a, a, **{key: v})
                self.assertIn("compare: " + key, str(e.exception))
                self.assertIn("from 0 to 3.40282e+38", str(e.exception))
        # shard=i/n: n held to --shard's range.
        with self.assertRaises(ValueError) as e:
            dw.tradeoff(shard="0/1000001")
        self.assertIn("--shard", str(e.exception))
        with self.assertRaises(TypeError):
            dw.compare(a, a, fail_threshold="0.1")
        self.assertEqual(dw.compare(a, a, warn_threshold=0, fail_threshold=np.float32(0.5))["fail_count"], 0)
        # Lists: an empty size list measures nothing, a light count given twice is one axis value.
        with self.assertRaises(ValueError) as e:
            dw.bench(sizes=[], frames=1)
        self.assertIn("sizes", str(e.exception))
        with self.assertRaises(ValueError):
            dw.bench(lights=[4, 4], **small)
        with self.assertRaises(ValueError):
            dw.bench(orbit=2, walkthrough=True, **small)
        for v in ((8,), (8, 8, 8), "8x8", 8):
            with self.assertRaises(TypeError, msg=repr(v)):
                dw.Session(size=v)
        self.assertEqual(s.size, SIZE)  # nothing above changed the session

    def test_an_experiment_record_is_refused_as_a_scene(self):
        s = dw.Session(scene="default", size=(16, 9))
        s.render("final")
        path = os.path.join(self.tmp.name, "as-scene-record.json")
        s.record(path)
        for call in (lambda: dw.Session(scene=path, size=(16, 9)), lambda: dw.bench(scene=path, sizes=[(8, 8)])):
            with self.assertRaises(dw.Error) as e:
                call()
            self.assertIn("experiment record", str(e.exception))
            self.assertIn("deferred-workbench replay", str(e.exception))
        # A preset as the scene: the same one definition (renderer/scene/SceneFileKind) names preset=.
        preset = os.path.join(self.tmp.name, "as-scene-preset.json")
        with open(preset, "w") as f:
            json.dump({"format": "deferred-workbench preset", "knobs": {"ssao.samples": 8}}, f)
        for call in (lambda: dw.Session(scene=preset, size=(16, 9)), lambda: dw.bench(scene=preset, sizes=[(8, 8)])):
            with self.assertRaises(dw.Error) as e:
                call()
            self.assertIn("this is a preset (knobs), not a scene", str(e.exception))
            self.assertIn("(preset= in Python)", str(e.exception))

    def test_bad_values_raise_and_never_crash(self):
        # None, wrong types, NaN, infinities, negative sizes, empty strings and missing files
        # through every function: each raises TypeError or ValueError (KnobError) or dw.Error with
        # a message, and the interpreter and the session go on.
        s = dw.Session(scene="default", size=(16, 9))
        s.render("final")
        missing = os.path.join(self.tmp.name, "missing", "file.exr")
        a = np.zeros((4, 4, 3), np.float32)
        bad = [None, "", float("nan"), float("inf"), -1, -2**70, (-4, -4), [], {}, b"x", missing]
        calls = {
            "Session(scene)": lambda v: dw.Session(scene=v, size=(8, 8)),
            "Session(size)": lambda v: dw.Session(size=v),
            "Session(preset)": lambda v: dw.Session(size=(8, 8), preset=v),
            "Session(settings)": lambda v: dw.Session(size=(8, 8), settings={"ssao.radius": v}),
            "set": lambda v: s.set("ssao.radius", v),
            "set(name)": lambda v: s.set(v, 1),
            "get": lambda v: s.get(v),
            "knob_info": lambda v: s.knob_info(v),
            "render": lambda v: s.render(v),
            "render(record)": lambda v: s.render("final", record=v),
            "write": lambda v: s.write("final", v),
            "dump_knobs": lambda v: s.dump_knobs(v),
            "record": lambda v: s.record(v),
            "probe": lambda v: s.probe(v, v),
            "resize": lambda v: s.resize(v, v),
            "reference": lambda v: s.reference(v),
            "reference(out)": lambda v: s.reference("ao", ao_rays=1, out=v),
            "reference(progress)": lambda v: s.reference("ao", ao_rays=1, progress=v),
            "load_image": lambda v: dw.load_image(v),
            "compare": lambda v: dw.compare(v, a),
            "compare(json)": lambda v: dw.compare(a, a, json=v),
            "bench(sizes)": lambda v: dw.bench(sizes=v, frames=1, warmup=0),
            "bench(scene)": lambda v: dw.bench(scene=v, sizes=[(8, 8)], frames=1, warmup=0),
            "tradeoff(size)": lambda v: dw.tradeoff(size=v, quiet=True),
            "tradeoff(metric)": lambda v: dw.tradeoff(size=(8, 8), metric=v, quiet=True),
        }
        allowed = (TypeError, ValueError, dw.Error)
        for name, call in calls.items():
            for v in bad:
                try:
                    call(v)
                except allowed as e:
                    self.assertTrue(str(e), "%s(%r): an empty message" % (name, v))
                    self.assertNotIn("Success", str(e), "%s(%r): %s" % (name, v, e))  # errno 0 as a reason
        # Arrays without pixels or channels (a division by zero once), NaN and 1-D arrays.
        for arr in (np.zeros((0, 0, 3), np.float32), np.zeros((4, 4, 0), np.float32), np.zeros((4,), np.float32),
                    np.full((4, 4, 3), np.nan, np.float32), np.array([[None]], object)):
            with self.assertRaises(allowed, msg=str(arr.shape)):
                dw.compare(arr, arr.copy())
        for empty in ("", None):
            for call in (lambda: s.write("final", empty), lambda: s.dump_knobs(empty), lambda: dw.load_image(empty)):
                with self.assertRaises((TypeError, ValueError)):
                    call()
        self.assertEqual(s.render("final").shape, (9, 16, 4))

    def test_compare_holds_arrays_to_the_image_memory_budget(self):
        # As compare on files (exit 4): a pair whose comparison would pass
        # DW_IMAGE_LIMIT_MB raises dw.Error with the CLI's message before a
        # pixel is copied (a 2000 x 2000 x 3 pair peaked at 2.6 GB under the
        # 1024 MB default); a budget that holds it compares it.
        a = np.zeros((512, 512, 3), np.float32)
        old = os.environ.get("DW_IMAGE_LIMIT_MB")
        try:
            os.environ["DW_IMAGE_LIMIT_MB"] = "1"
            with self.assertRaises(dw.Error) as caught:
                dw.compare(a, a)
            self.assertIn("compare: reference is 512 x 512 pixels of 3 channels: comparing it takes about", str(caught.exception))
            self.assertIn("over the image memory limit of 1 MB (set DW_IMAGE_LIMIT_MB=MB to raise it)", str(caught.exception))
            with self.assertRaises(dw.Error) as caught:
                dw.compare(np.zeros((4, 4, 3), np.float32), a)
            self.assertIn("compare: test is 512 x 512 pixels", str(caught.exception))
            os.environ["DW_IMAGE_LIMIT_MB"] = "1024"
            self.assertEqual(dw.compare(a, a)["fail_count"], 0)
        finally:
            if old is None:
                os.environ.pop("DW_IMAGE_LIMIT_MB", None)
            else:
                os.environ["DW_IMAGE_LIMIT_MB"] = old

    def test_reference_and_compare_write_their_files(self):
        s = dw.Session(scene="default", size=(32, 18))
        out = os.path.join(self.tmp.name, "ref-ao.exr")
        stats_out = os.path.join(self.tmp.name, "ref-ao.json")
        ao = s.reference("ao", ao_rays=4, cache=False, out=out, stats_out=stats_out)
        self.assertTrue(np.array_equal(dw.load_image(out)[..., :1], ao))
        with open(stats_out) as f:
            stats = json.load(f)
        self.assertEqual((stats["primary_rays"], stats["width"], stats["height"]), (32 * 18, 32, 18))
        self.assertEqual(stats["ao_rays_per_pixel"], 4)

        a = np.zeros((16, 16, 3), np.float32)
        b = a.copy()
        b[3, 5, 1] = 0.5
        error_map = os.path.join(self.tmp.name, "err.exr")
        heat_map = os.path.join(self.tmp.name, "err.png")
        report = os.path.join(self.tmp.name, "err.json")
        r = dw.compare(a, b, error_map=error_map, heat_map=heat_map, json=report)
        with open(report) as f:
            self.assertEqual(json.load(f)["max"], r["max"])
        err = dw.load_image(error_map)  # absdiff.R/G/B, ssim, flip: one channel holds the 0.5
        self.assertEqual(err.shape[:2], (16, 16))
        self.assertIn(0.5, [round(float(v), 6) for v in err[3, 5]])
        heat = dw.load_image(heat_map)
        self.assertEqual(heat.shape, (16, 16, 3))
        self.assertFalse(np.array_equal(heat[3, 5], heat[0, 0]))  # the differing pixel stands out
        with self.assertRaises(Exception):
            dw.compare(a, b, error_map=os.path.join(self.tmp.name, "err.png"))


if __name__ == "__main__":
    unittest.main()
