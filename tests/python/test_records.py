"""Experiment records (issue 24): `render --record`, `bench --json` and
`replay`, through the CLI (DW_WORKBENCH_BINARY). The same record replays to
the same image bit for bit (exit 0); a changed scene file (a glTF's .bin
included), knob or build field is named; a version 1 record still replays; a
record of a newer format version is refused with its version named (exit 2);
a bench record runs its grid again and compares each configuration."""
import hashlib
import json
import os
import re
import shutil
import struct
import subprocess
import tempfile
import unittest

BINARY = os.environ["DW_WORKBENCH_BINARY"]
SCENES = os.path.join(os.path.dirname(__file__), "..", "..", "scenes")
FIXTURES = os.path.join(os.path.dirname(__file__), "..", "records")


SHADERS = os.path.join(os.path.dirname(__file__), "..", "..", "shaders")


def run(*args, cwd=None, timeout=None, env=None):
    return subprocess.run([BINARY] + list(args), capture_output=True, text=True, cwd=cwd, timeout=timeout,
                          env=None if env is None else dict(os.environ, **env))


class RecordTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.scene = os.path.join(cls.tmp.name, "spotlights.json")
        shutil.copy(os.path.join(SCENES, "spotlights.json"), cls.scene)
        cls.record = os.path.join(cls.tmp.name, "r.json")
        r = run("render", "--scene", cls.scene, "--size", "64x36", "--frames", "6", "--warmup", "1", "--set",
                "ssao.samples=8", "--out", os.path.join(cls.tmp.name, "a.png"), "--record", cls.record)
        assert r.returncode == 0, r.stderr
        with open(cls.record) as f:
            cls.data = json.load(f)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def variant(self, name, change):
        data = json.loads(json.dumps(self.data))
        change(data)
        path = os.path.join(self.tmp.name, name)
        with open(path, "w") as f:
            json.dump(data, f)
        return path

    def test_record_holds_the_run(self):
        d = self.data
        self.assertEqual(d["format"], "deferred-workbench record")
        self.assertEqual(d["version"], 2)
        self.assertEqual(d["command"], "render")
        self.assertEqual(d["camera_path"], {"mode": "fixed"})
        self.assertEqual(d["seeds"], {"bootstrap": "12345"})
        self.assertEqual(d["results"]["metrics"], {})
        self.assertEqual(d["size"], [64, 36])
        self.assertEqual((d["frames"], d["warmup"]), (6, 1))
        self.assertEqual(d["knobs"]["ssao.samples"], "8")
        self.assertEqual(d["scene"]["files"][0]["path"], self.scene)
        self.assertEqual(len(d["scene"]["files"][0]["sha256"]), 64)
        self.assertEqual(len(d["results"]["image"]["sha256"]), 64)
        frame = next(s for s in d["results"]["timings"] if s["name"] == "frame")
        self.assertEqual(len(frame["gpu_ms"]), 6)
        # The median of the six frames, and a bootstrap interval around it.
        ordered = sorted(frame["gpu_ms"])
        self.assertAlmostEqual(frame["gpu"]["median"], (ordered[2] + ordered[3]) / 2)
        low, high = frame["gpu"]["ci95"]
        self.assertLessEqual(low, frame["gpu"]["median"])
        self.assertGreaterEqual(high, frame["gpu"]["median"])
        self.assertGreaterEqual(low, min(frame["gpu_ms"]))
        self.assertLessEqual(high, max(frame["gpu_ms"]))
        for key in ("version", "commit", "compiler", "build_type", "cxx_flags"):
            self.assertIn(key, d["build"])
        self.assertIn("renderer", d["gl"])
        self.assertIn("cpu", d["host"])

    def test_replay_gives_the_same_image(self):
        r = run("replay", self.record)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("image: identical", r.stdout)
        self.assertRegex(r.stdout, r"counters: the same \([0-9]+ compared, exactly\)")
        self.assertRegex(r.stdout, r"timing frame +gpu median +[0-9.]+ -> +[0-9.]+ ms  x[0-9.]+ \[[0-9.]+, [0-9.]+\]")
        self.assertNotIn("too few frames", r.stdout)
        self.assertNotIn("scene file", r.stdout)

    def test_a_moved_counter_is_named_and_makes_the_replay_differ(self):
        frame = next(t for t in self.data["results"]["timings"] if t["name"] == "frame")
        self.assertGreater(frame["counters"]["fragments"], 0)  # the frame's sum over its passes
        self.assertGreater(frame["counters"]["bytes"], 0)

        def bump(data):
            series = next(t for t in data["results"]["timings"] if t["name"] == "frame")
            series["counters"]["fragments"] += 1
        r = run("replay", self.variant("moved-counter.json", bump))
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("counters: moved: fragments.frame %d -> %d" % (frame["counters"]["fragments"] + 1,
                                                                     frame["counters"]["fragments"]), r.stdout)
        self.assertIn("image: identical", r.stdout)

    def test_replay_refuses_to_write_over_the_record_it_replays(self):
        # The record replayed is the baseline: --record over it would lose it (it was overwritten in silence).
        with open(self.record, "rb") as f:
            before = f.read()
        r = run("replay", self.record, "--record", self.record)
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("that is the record being replayed", r.stderr)
        with open(self.record, "rb") as f:
            self.assertEqual(f.read(), before)

    def test_a_merge_record_is_named_as_one(self):
        # bench merge's record has no grid to run again: replay says so (it said 'frames: 0 is outside --frames's range').
        d = tempfile.mkdtemp(dir=self.tmp.name)
        for i in range(2):
            r = run("bench", "--scene", "default", "--size", "16x9", "--lights", "1,2", "--frames", "1", "--shard",
                    "%d/2" % i, "--csv", "s%d.csv" % i, "--record", "s%d.json" % i, "--quiet", cwd=d)
            self.assertEqual(r.returncode, 0, r.stderr)
        r = run("bench", "merge", "s0.csv", "s1.csv", "--out", "all.csv", "--record", "all.json", cwd=d)
        self.assertEqual(r.returncode, 0, r.stderr)  # shards written with --record merge
        r = run("replay", "all.json", cwd=d)
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("a bench merge record has no grid to run again", r.stderr)

    def test_too_few_frames_give_no_interval(self):
        # Below 6 counted frames a median has no 95% interval worth the name:
        # the record says so instead of numbers, and so does replay.
        record = os.path.join(self.tmp.name, "two-frames.json")
        r = run("render", "--scene", self.scene, "--size", "32x18", "--frames", "2", "--warmup", "0",
                "--out", os.path.join(self.tmp.name, "two.png"), "--record", record)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(record) as f:
            d = json.load(f)
        frame = next(s for s in d["results"]["timings"] if s["name"] == "frame")
        self.assertEqual(len(frame["gpu_ms"]), 2)
        self.assertIsNone(frame["gpu"]["ci95"])
        self.assertEqual(frame["gpu"]["interval"], "too few frames for an interval (2 counted, 6 needed)")
        self.assertAlmostEqual(frame["gpu"]["median"], sum(frame["gpu_ms"]) / 2)
        r = run("replay", record)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        line = next(l for l in r.stdout.splitlines() if l.startswith("timing frame"))
        self.assertIn("too few frames for an interval (2 and 2 frames, 6 needed on each side)", line)
        self.assertNotIn("[", line)

    def test_a_changed_knob_value_changes_the_image(self):
        path = self.variant("knob.json", lambda d: d["knobs"].__setitem__("tonemap.operator", "aces"))
        r = run("replay", path)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("image: differs (sha256 " + self.data["results"]["image"]["sha256"] + " -> ", r.stdout)

    def test_knobs_the_build_lacks_or_adds_are_named(self):
        def change(d):
            d["knobs"]["ssao.retired_knob"] = "3"
            del d["knobs"]["bloom.enabled"]
        r = run("replay", self.variant("knobs.json", change))
        self.assertIn("knob not in this build: ssao.retired_knob (recorded 3)", r.stdout)
        self.assertIn("knob new in this build: bloom.enabled", r.stdout)

    def test_a_changed_build_is_named(self):
        path = self.variant("build.json", lambda d: d["build"].__setitem__("commit", "0123abc"))
        r = run("replay", path)
        self.assertIn("build commit: 0123abc -> ", r.stdout)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)  # the same image all the same

    def test_a_changed_scene_file_is_named(self):
        scene = os.path.join(self.tmp.name, "changed.json")
        shutil.copy(self.scene, scene)
        record = os.path.join(self.tmp.name, "changed-record.json")
        r = run("render", "--scene", scene, "--size", "32x18", "--out", os.path.join(self.tmp.name, "c.png"),
                "--record", record)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(scene) as f:
            data = json.load(f)
        data["lighting"]["lights"][0]["intensity"] = [0.1, 3, 0.1]
        with open(scene, "w") as f:
            json.dump(data, f)
        r = run("replay", record)
        self.assertIn("scene file changed: " + scene, r.stdout)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("image: differs", r.stdout)

    def test_newer_and_broken_records_are_refused(self):
        r = run("replay", self.variant("v99.json", lambda d: d.__setitem__("version", 99)))
        self.assertEqual(r.returncode, 2)
        self.assertIn("record version 99 is newer than this build reads (2)", r.stderr)
        r = run("replay", self.variant("nosize.json", lambda d: d.pop("size")))
        self.assertEqual(r.returncode, 2)
        self.assertIn("size", r.stderr)
        deep = os.path.join(self.tmp.name, "deep.json")
        with open(deep, "w") as f:
            f.write("[" * 5000 + "]" * 5000)
        r = run("replay", deep)
        self.assertEqual(r.returncode, 2)
        self.assertIn("nested deeper", r.stderr)
        r = run("replay", os.path.join(self.tmp.name, "absent.json"))
        self.assertEqual(r.returncode, 2)
        # Fields of the wrong type or shape: refused with the record version and the field, never a crash.
        broken = {
            "size-text.json": lambda d: d.__setitem__("size", "64x36"),
            "camera-path.json": lambda d: d.__setitem__("camera_path", {"mode": 3}),
            "timings.json": lambda d: d["results"].__setitem__("timings", [{"name": "frame", "gpu_ms": "fast"}]),
            "bench-no-grid.json": lambda d: d.__setitem__("command", "bench"),
            "tradeoff.json": lambda d: d.__setitem__("command", "tradeoff"),
            "v1-bench.json": lambda d: d.update({"version": 1, "command": "bench"}),
        }
        for name, change in broken.items():
            r = run("replay", self.variant(name, change))
            self.assertEqual(r.returncode, 2, name + ": " + r.stdout + r.stderr)
            self.assertIn("refused: " + os.path.join(self.tmp.name, name), r.stderr)
        # A scene file that is gone: the record cannot be restored, and the refusal names it.
        gone = self.variant("gone.json", lambda d: d["scene"].update(
            {"spec": os.path.join(self.tmp.name, "gone-scene.json"),
             "files": [{"path": os.path.join(self.tmp.name, "gone-scene.json"), "sha256": "ab" * 32}]}))
        r = run("replay", gone)
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("cannot restore it", r.stderr)
        self.assertIn(os.path.join(self.tmp.name, "gone-scene.json"), r.stderr)
        r = run("replay", self.variant("paint.json", lambda d: d.__setitem__("command", "paint")))
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("unknown command 'paint' (render, bench, tradeoff or gui)", r.stderr)

    def test_a_version_1_record_still_replays(self):
        # tests/records/v1-render-default.json: what render --record wrote before version 2.
        fixture = os.path.join(FIXTURES, "v1-render-default.json")
        new = os.path.join(self.tmp.name, "from-v1.json")
        r = run("replay", fixture, "--record", new)
        self.assertIn(r.returncode, (0, 1), r.stdout + r.stderr)
        self.assertIn("record version 1, read as version 2", r.stdout)
        self.assertNotIn("knob value refused", r.stdout)
        self.assertIn("timing frame", r.stdout)
        with open(fixture) as f:
            old = json.load(f)
        with open(new) as f:
            again = json.load(f)
        # Migrated: what the record held is what ran (the knobs it recorded, its camera and size).
        self.assertEqual(again["version"], 2)
        self.assertEqual(again["camera"], old["camera"])
        self.assertEqual(again["size"], old["size"])
        renamed = {"ssao.enabled": "ao.enabled", "fxaa.enabled": "aa.method"}  # KnobRegistry::addAlias
        values = {("fxaa.enabled", "true"): "fxaa", ("fxaa.enabled", "false"): "none"}  # its value aliases
        for name, value in old["knobs"].items():
            self.assertEqual(again["knobs"][renamed.get(name, name)], values.get((name, value), value), name)
        self.assertEqual(again["results"]["image"]["width"], old["results"]["image"]["width"])

    def test_an_old_knob_name_in_a_record_restores_the_knob_it_became(self):
        # The version 1 fixture names ssao.enabled, now ao.enabled (an alias):
        # replay restores it by its new name instead of calling it missing.
        fixture = os.path.join(FIXTURES, "v1-render-default.json")
        with open(fixture) as f:
            old = json.load(f)
        self.assertIn("ssao.enabled", old["knobs"])
        old["knobs"]["ssao.enabled"] = "false"
        path = os.path.join(self.tmp.name, "v1-ao-off.json")
        with open(path, "w") as f:
            json.dump(old, f)
        new = os.path.join(self.tmp.name, "v1-ao-off-again.json")
        r = run("replay", path, "--record", new)
        self.assertIn(r.returncode, (0, 1), r.stdout + r.stderr)
        self.assertIn("knob renamed: ssao.enabled -> ao.enabled (recorded false)", r.stdout)
        self.assertNotIn("knob not in this build: ssao.enabled", r.stdout)
        self.assertNotIn("knob new in this build: ao.enabled", r.stdout)
        with open(new) as f:
            again = json.load(f)
        self.assertEqual(again["knobs"]["ao.enabled"], "false")
        self.assertNotIn("ssao.enabled", again["knobs"])

    def test_a_gltf_scene_records_its_buffers_and_images(self):
        folder = os.path.join(self.tmp.name, "gltf")
        os.makedirs(folder, exist_ok=True)
        # One textured triangle: positions and texture coordinates in tri.bin, the texture a PNG.
        data = struct.pack("<9f", -1, -1, 0, 1, -1, 0, 0, 1, 0) + struct.pack("<6f", 0, 0, 1, 0, 0.5, 1)
        with open(os.path.join(folder, "tri.bin"), "wb") as f:
            f.write(data)
        shutil.copy(os.path.join(self.tmp.name, "a.png"), os.path.join(folder, "tex.png"))
        gltf = {
            "asset": {"version": "2.0"},
            "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
            "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
            "textures": [{"source": 0}], "images": [{"uri": "tex.png"}],
            "buffers": [{"uri": "tri.bin", "byteLength": 60}],
            "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                            {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [-1, -1, 0], "max": [1, 1, 0]},
                          {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
        }
        with open(os.path.join(folder, "tri.gltf"), "w") as f:
            json.dump(gltf, f)
        scene = os.path.join(folder, "scene.json")
        with open(scene, "w") as f:
            json.dump({"name": "triangle", "objects": [{"gltf": "tri.gltf"}]}, f)
        record = os.path.join(folder, "record.json")
        r = run("render", "--scene", scene, "--size", "32x18", "--out", os.path.join(folder, "t.png"),
                "--record", record)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(record) as f:
            files = [x["path"] for x in json.load(f)["scene"]["files"]]
        self.assertEqual(sorted(os.path.basename(p) for p in files), ["scene.json", "tex.png", "tri.bin", "tri.gltf"])
        # A changed .bin is named by path, as the scene file is.
        with open(os.path.join(folder, "tri.bin"), "r+b") as f:
            f.seek(0)
            f.write(struct.pack("<f", -0.5))
        r = run("replay", record)
        self.assertIn("scene file changed: " + os.path.join(folder, "tri.bin"), r.stdout)
        self.assertNotIn("scene file changed: " + scene, r.stdout)

    def test_fields_out_of_the_options_range_are_refused_by_name(self):
        # The limits of the options each field stands for (--frames 1..100000,
        # --warmup 0..100000, --size 1..16384), knob values through the
        # registry, the camera through scene/CameraCheck: exit 2 naming the field.
        cases = {
            "frames-big.json": (lambda d: d.__setitem__("frames", 100001),
                                "frames: 100001 is outside --frames's range 1..100000"),
            "frames-zero.json": (lambda d: d.__setitem__("frames", 0), "frames: 0 is outside --frames's range"),
            "warmup.json": (lambda d: d.__setitem__("warmup", 100001), "warmup: 100001 is outside --warmup's range"),
            "size.json": (lambda d: d.__setitem__("size", [64, 20000]), "size height: 20000 is outside --size's range"),
            "knob.json": (lambda d: d["knobs"].__setitem__("ssao.samples", "100000"), "knobs.ssao.samples: "),
            "enum.json": (lambda d: d["knobs"].__setitem__("tonemap.operator", "sepia"), "knobs.tonemap.operator: "),
            "up.json": (lambda d: d["camera"].__setitem__("up", [0, 0, 0]), "camera.up: "),
            "fov.json": (lambda d: d["camera"].__setitem__("fov_y_degrees", 180), "camera.fov_y_degrees: "),
            "near.json": (lambda d: d["camera"].__setitem__("near", 0), "camera.near: "),
        }
        for name, (change, message) in cases.items():
            # Refused before anything renders (an old build rendered 100001 frames).
            r = run("replay", self.variant("range-" + name, change), timeout=120)
            self.assertEqual(r.returncode, 2, name + ": " + r.stdout + r.stderr)
            self.assertIn("refused: " + os.path.join(self.tmp.name, "range-" + name), r.stderr)
            self.assertIn(message, r.stderr, name)
            self.assertNotIn("image:", r.stdout, name)

    def test_a_record_replays_from_any_directory(self):
        # Written from a project folder with the record in a subfolder and the
        # scene named relative to the working directory: the record keeps it
        # relative to its own folder, so replay works from anywhere, and after
        # the folder moved.
        project = os.path.join(self.tmp.name, "project")
        os.makedirs(os.path.join(project, "out"), exist_ok=True)
        shutil.copy(self.scene, os.path.join(project, "spotlights.json"))
        r = run("render", "--scene", "spotlights.json", "--size", "32x18", "--out", "out/p.png",
                "--record", "out/rec.json", cwd=project)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(project, "out", "rec.json")) as f:
            d = json.load(f)
        self.assertEqual(d["scene"]["spec"], "../spotlights.json")
        self.assertEqual(d["scene"]["files"][0]["path"], "../spotlights.json")
        elsewhere = os.path.join(self.tmp.name, "elsewhere")
        os.makedirs(elsewhere, exist_ok=True)
        r = run("replay", os.path.join(project, "out", "rec.json"), cwd=elsewhere)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("image: identical", r.stdout)
        self.assertNotIn("scene file", r.stdout)
        moved = os.path.join(self.tmp.name, "moved")
        shutil.copytree(project, moved)
        r = run("replay", os.path.join("..", "moved", "out", "rec.json"), cwd=elsewhere)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertNotIn("scene file", r.stdout)
        # A record whose relative paths were written against the working
        # directory (before they were kept relative to the record) still
        # replays from that directory.
        d["scene"].update({"spec": "spotlights.json", "source": "spotlights.json",
                           "files": [{"path": "spotlights.json", "sha256": d["scene"]["files"][0]["sha256"]}]})
        with open(os.path.join(project, "out", "legacy.json"), "w") as f:
            json.dump(d, f)
        r = run("replay", "out/legacy.json", cwd=project)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertNotIn("scene file", r.stdout)

    def test_scene_files_are_the_loaders_never_the_records(self):
        # The record names a path the scene does not read (a named pipe, which
        # would block whoever opened it) and lacks one it does read: replay
        # reports both by name and opens neither path it was only told about.
        fifo = os.path.join(self.tmp.name, "not-a-scene-file")
        if not os.path.exists(fifo):
            os.mkfifo(fifo)
        def change(d):
            d["scene"]["files"] = [{"path": fifo, "sha256": "cd" * 32}]
        r = run("replay", self.variant("files.json", change), timeout=300)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("scene file removed: " + fifo + " (recorded sha256 cdcdcdcdcdcdcdcd; the scene no longer reads it)",
                      r.stdout)
        self.assertIn("scene file added: " + self.scene + " (sha256 " + self.data["scene"]["files"][0]["sha256"][:16],
                      r.stdout)
        self.assertIn("image: identical", r.stdout)

    def test_bench_json_is_a_record_and_replays_the_grid(self):
        csv = os.path.join(self.tmp.name, "b.csv")
        record = os.path.join(self.tmp.name, "b.json")
        r = run("bench", "--scene", self.scene, "--size", "32x18", "--sweep", "ssao.samples=4,8", "--frames", "3",
                "--warmup", "1", "--seed", "7", "--quiet", "--csv", csv, "--json", record)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(record) as f:
            d = json.load(f)
        self.assertEqual((d["format"], d["version"], d["command"]), ("deferred-workbench record", 2, "bench"))
        self.assertEqual(d["grid"]["sizes"], ["32x18"])
        self.assertEqual(d["grid"]["sweep"], [{"knob": "ssao.samples", "values": ["4", "8"]}])
        self.assertEqual(d["seeds"]["lights"], "7")
        self.assertEqual((d["frames"], d["warmup"]), (3, 1))
        self.assertEqual(d["scene"]["files"][0]["path"], self.scene)
        self.assertIn("ssao.samples", d["knobs"])
        self.assertIn("cxx_flags", d["build"])
        configs = d["results"]["configs"]
        self.assertEqual([c["knobs"]["ssao.samples"] for c in configs], ["4", "8"])
        for c in configs:
            self.assertEqual(len(c["samples"]), 3)
            gpu = c["series"]["frame"]["gpu_ms"]
            frames = sorted(x["gpu_ms"]["frame"] for x in c["samples"])
            self.assertAlmostEqual(gpu["median"], frames[1], places=3)
            self.assertLessEqual(gpu["ci95"][0], gpu["median"])
            self.assertGreaterEqual(gpu["ci95"][1], gpu["median"])
            self.assertGreaterEqual(gpu["ci95"][0], frames[0] - 1e-4)
            self.assertLessEqual(gpu["ci95"][1], frames[2] + 1e-4)

        # Replay: the same grid again, each configuration's frame median old -> new.
        again = os.path.join(self.tmp.name, "b-again.json")
        r = run("replay", record, "--record", again)
        self.assertIn(r.returncode, (0, 1), r.stdout + r.stderr)
        for c in configs:
            frames = sorted(s["gpu_ms"]["frame"] for s in c["samples"])
            m = re.search(r"config %d \(32x18, \d+ lights, ssao\.samples=%s\): frame gpu median +([0-9.]+) ->"
                          % (c["config"], c["knobs"]["ssao.samples"]), r.stdout)
            self.assertIsNotNone(m, r.stdout)
            self.assertAlmostEqual(float(m.group(1)), frames[1], delta=0.0006)  # printed with %.3f
        # Lights per pixel are counted, not timed: equal on the same machine.
        lpp = re.findall(r"lpp ([0-9.]+) -> ([0-9.]+)", r.stdout)
        self.assertEqual(len(lpp), 2, r.stdout)
        for old, new in lpp:
            self.assertEqual(old, new)
        self.assertNotIn("not in the record", r.stdout)
        self.assertRegex(r.stdout, r"bench: (the same|differs \(0 configuration\(s\) with other lights per pixel)")
        with open(again) as f:
            a = json.load(f)
        self.assertEqual(a["grid"], d["grid"])
        self.assertEqual(a["seeds"], d["seeds"])
        self.assertEqual(len(a["results"]["configs"]), 2)

        # bench merge reads the record's results (its settings and baseline) and writes a record too.
        merged_json = os.path.join(self.tmp.name, "merged.json")
        r = run("bench", "merge", csv, "--out", os.path.join(self.tmp.name, "merged.csv"), "--json", merged_json)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(merged_json) as f:
            m = json.load(f)
        self.assertEqual((m["command"], m["grid"]), ("bench", {"merged": True}))
        self.assertEqual(m["results"]["settings"]["frames"], "3")
        self.assertEqual(len(m["results"]["configs"]), 2)
        r = run("replay", merged_json)
        self.assertEqual(r.returncode, 2)
        self.assertIn("a bench merge record has no grid to run again", r.stderr)


    def test_shader_files_are_recorded_and_a_changed_one_is_named(self):
        d = self.data
        shaders = {f["path"]: f["sha256"] for f in d["shaders"]["files"]}
        self.assertEqual(os.path.realpath(d["shaders"]["folder"]), os.path.realpath(SHADERS))
        # The stage files and what they include (params/ headers), not a glob of the folder.
        for name in ("ssao/ssao.frag", "params/ssao.h", "common/gbuffer.glsl", "tonemap/tonemap.frag"):
            self.assertIn(name, shaders)
            with open(os.path.join(SHADERS, name), "rb") as f:
                self.assertEqual(shaders[name], hashlib.sha256(f.read()).hexdigest(), name)
        # An unchanged copy of the folder: no shader line, the same image.
        copy = os.path.join(self.tmp.name, "shaders-copy")
        if not os.path.exists(copy):
            shutil.copytree(SHADERS, copy)
        r = run("replay", self.record, env={"DW_SHADER_DIR": copy})
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertNotIn("shader", r.stdout)
        self.assertIn("inputs changed: none\nimage: identical", r.stdout)
        # A mistyped or empty folder is refused, never passed over for the build's own shaders
        # (which replayed "identical" with no word of the folder asked for).
        empty = os.path.join(self.tmp.name, "shaders-empty")
        os.makedirs(empty, exist_ok=True)
        for folder in (os.path.join(self.tmp.name, "no-such-shaders"), empty):
            r = run("replay", self.record, env={"DW_SHADER_DIR": folder})
            self.assertNotEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertIn("DW_SHADER_DIR=" + folder + " is not a shader folder (" +
                          ("it has no common/ in it" if folder == empty else "it does not exist"), r.stderr)
            self.assertNotIn("image: identical", r.stdout)
        # One comment edited: that file is named, before the image line;
        # the image is the same, so the exit code is 0 (the image decides).
        edited = os.path.join(self.tmp.name, "shaders-edited")
        shutil.copytree(SHADERS, edited)
        with open(os.path.join(edited, "ssao", "ssao.frag"), "a") as f:
            f.write("// a comment added after the record\n")
        r = run("replay", self.record, env={"DW_SHADER_DIR": edited})
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        lines = r.stdout.splitlines()
        changed = [l for l in lines if l.startswith("shader file")]
        self.assertEqual(len(changed), 1, r.stdout)
        self.assertTrue(changed[0].startswith("shader file changed: ssao/ssao.frag (sha256 " +
                                              shaders["ssao/ssao.frag"][:16] + " -> "), changed[0])
        self.assertIn("inputs changed (1): shader file ssao/ssao.frag", lines)
        self.assertLess(lines.index(changed[0]), lines.index("image: identical"))
        # A line changed in the tonemap shader: named, and the image differs (exit 1).
        with open(os.path.join(SHADERS, "tonemap", "tonemap.frag")) as f:
            tonemap = f.read()
        with open(os.path.join(edited, "tonemap", "tonemap.frag"), "w") as f:
            f.write(tonemap.rstrip().rsplit("}", 1)[0] + "    outColor.rgb *= 0.5;\n}\n")
        r = run("replay", self.record, env={"DW_SHADER_DIR": edited})
        self.assertIn("shader file changed: tonemap/tonemap.frag", r.stdout, r.stderr)
        self.assertIn("inputs changed (2): shader file ssao/ssao.frag, shader file tonemap/tonemap.frag", r.stdout)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("image: differs", r.stdout)
        # A record without the field (written before shader hashes) still replays, and says so once.
        r = run("replay", self.variant("no-shaders.json", lambda d: d.pop("shaders")))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertEqual(r.stdout.count("record holds no shader hashes"), 1, r.stdout)

    def test_the_image_decides_the_exit_code_and_changed_inputs_are_listed(self):
        # Changed inputs, the same image: exit 0, every changed input named on one line.
        def change(d):
            d["build"]["commit"] = "0123abc"
            d["knobs"]["ssao.retired_knob"] = "3"
        r = run("replay", self.variant("inputs.json", change))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        line = next(l for l in r.stdout.splitlines() if l.startswith("inputs changed"))
        # The record was edited to change them: said first, and named among the inputs.
        self.assertIn("record edited: its inputs no longer match the sha256 written with them", r.stdout)
        self.assertEqual(line, "inputs changed (3): record inputs edited, knob ssao.retired_knob, build commit")
        self.assertTrue(r.stdout.endswith(line + "\nimage: identical\n"), r.stdout)
        # No input changed, another image (the record's value is restored, not the build's): exit 1.
        r = run("replay", self.variant("image.json", lambda d: d["results"]["image"].__setitem__("sha256", "ab" * 32)))
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        # An edited result is told from a changed machine: "record edited", not "inputs changed: none".
        self.assertIn("record edited: its results no longer match the sha256 written with them", r.stdout)
        self.assertNotIn("record edited: its inputs", r.stdout)
        self.assertIn("inputs changed (1): record results edited\nimage: differs (sha256 " + "ab" * 32 + " -> ", r.stdout)
        # Without its own sha256s (a record written before them) the same edit reads as before, and replay says why.
        r = run("replay", self.variant("image-unhashed.json", lambda d: (
            d["results"]["image"].__setitem__("sha256", "ab" * 32), d.pop("record_sha256"))))
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("record holds no sha256 of its own (written before records kept one)", r.stdout)
        self.assertIn("inputs changed: none\nimage: differs (sha256 " + "ab" * 32 + " -> ", r.stdout)
        r = run("help", "replay")
        self.assertIn("Exit codes: the result decides, not the inputs", r.stdout + r.stderr)

    def test_a_record_holds_its_own_sha256s_and_an_unedited_one_replays_unflagged(self):
        self.assertRegex(self.data["record_sha256"]["inputs"], r"^[0-9a-f]{64}$")
        self.assertRegex(self.data["record_sha256"]["results"], r"^[0-9a-f]{64}$")
        # Re-indented and keys reordered (another JSON writer) is not an edit.
        path = os.path.join(self.tmp.name, "reindented.json")
        with open(path, "w") as f:
            json.dump(dict(reversed(list(self.data.items()))), f, indent=7)
        r = run("replay", path)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertNotIn("record edited", r.stdout)
        self.assertNotIn("holds no sha256", r.stdout)
        self.assertIn("inputs changed: none\nimage: identical", r.stdout)
        # A wrong type is refused by its path.
        r = run("replay", self.variant("badsha.json", lambda d: d["record_sha256"].__setitem__("inputs", 3)))
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("record_sha256.inputs: expects a string, got 3", r.stderr)

    def test_a_built_in_scene_records_its_content_hash(self):
        record = os.path.join(self.tmp.name, "builtin.json")
        r = run("render", "--scene", "default", "--size", "32x18", "--out", os.path.join(self.tmp.name, "b.png"),
                "--record", record)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(record) as f:
            d = json.load(f)
        entry = dict(d["scene"]["files"][0])
        self.assertEqual(entry["path"], "builtin:default")
        self.assertRegex(entry["sha256"], r"^[0-9a-f]{64}$")
        # Another built-in has another content hash; the same one the same.
        other = os.path.join(self.tmp.name, "builtin-spheres.json")
        self.assertEqual(run("render", "--scene", "spheres", "--size", "32x18", "--out",
                             os.path.join(self.tmp.name, "c.png"), "--record", other).returncode, 0)
        with open(other) as f:
            self.assertNotEqual(json.load(f)["scene"]["files"][0]["sha256"], entry["sha256"])
        r = run("replay", record)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("inputs changed: none\nimage: identical", r.stdout)
        # A built-in generated differently than when recorded (its recorded hash another one): named as a scene input.
        changed = os.path.join(self.tmp.name, "builtin-changed.json")
        d["scene"]["files"][0]["sha256"] = "cd" * 32
        with open(changed, "w") as f:
            json.dump(d, f)
        r = run("replay", changed)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("scene file changed: builtin:default (sha256 cdcdcdcdcdcdcdcd -> %s)" % entry["sha256"][:16], r.stdout)
        self.assertIn("inputs changed (2): record inputs edited, scene file builtin:default", r.stdout)
        # A record of a built-in written before the content hash: said once, not an added file.
        d["scene"]["files"] = []
        d.pop("record_sha256")
        with open(changed, "w") as f:
            json.dump(d, f)
        r = run("replay", changed)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("record holds no content hash of the built-in scene (written before records kept one)", r.stdout)
        self.assertIn("inputs changed: none\nimage: identical", r.stdout)

    def test_replay_diff_names_what_differs_between_two_records(self):
        other = os.path.join(self.tmp.name, "r16.json")
        r = run("render", "--scene", self.scene, "--size", "64x36", "--frames", "6", "--warmup", "1", "--set",
                "ssao.samples=16", "--out", os.path.join(self.tmp.name, "a16.png"), "--record", other)
        self.assertEqual(r.returncode, 0, r.stderr)
        r = run("replay", "--diff", self.record, other)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        lines = r.stdout.splitlines()
        self.assertIn("knob ssao.samples: 8 -> 16", lines)
        self.assertIn("inputs changed (1): knob ssao.samples", lines)
        self.assertRegex(r.stdout, r"timing frame +gpu median +[0-9.]+ -> +[0-9.]+ ms  x[0-9.]+ \[[0-9.]+, [0-9.]+\]")
        with open(other) as f:
            other_sha = json.load(f)["results"]["image"]["sha256"]
        self.assertEqual(lines[-1], "image: differs (sha256 %s -> %s)" % (self.data["results"]["image"]["sha256"], other_sha))
        # A record against itself: nothing differs, exit 0.
        r = run("replay", "--diff", self.record, self.record)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("inputs changed: none", r.stdout.splitlines())
        self.assertEqual(r.stdout.splitlines()[-1], "image: identical")
        self.assertNotIn("record edited", r.stdout)
        # Build, GL, seeds and camera fields in replay's words; an edited side named.
        def change(d):
            d["build"]["commit"] = "0123abc"
            d["gl"]["renderer"] = "another GPU"
            d["seeds"]["bootstrap"] = "7"
            d["camera"]["fov_y_degrees"] = 33.0
        edited = self.variant("diff-edited.json", change)
        r = run("replay", "--diff", self.record, edited)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        lines = r.stdout.splitlines()
        self.assertIn("diff-edited.json: record edited: its inputs no longer match the sha256 written with them "
                      "(record_sha256.inputs %s, now " % self.data["record_sha256"]["inputs"][:16], r.stdout)
        self.assertIn("build commit: %s -> 0123abc" % self.data["build"]["commit"], lines)
        self.assertIn("gl renderer: %s -> another GPU" % self.data["gl"]["renderer"], lines)
        self.assertIn("seed bootstrap: 12345 -> 7", lines)
        self.assertIn("camera.fov_y_degrees: %s -> 33.0" % json.dumps(self.data["camera"]["fov_y_degrees"]), lines)
        self.assertIn("inputs changed (5): diff-edited.json: record inputs edited, seed bootstrap, "
                      "camera.fov_y_degrees, build commit, gl renderer", lines)
        # Bad input: exit 2 naming the file; usage errors.
        r = run("replay", "--diff", self.record, os.path.join(self.tmp.name, "missing.json"))
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("missing.json", r.stderr)
        r = run("replay", "--diff", self.record)
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("replay --diff needs two record files", r.stderr)

    def test_a_tradeoff_against_the_reference_records_its_seed_and_replays_with_it(self):
        record = os.path.join(self.tmp.name, "seed-t.json")
        env = {"DW_REFERENCE_CACHE": os.path.join(self.tmp.name, "refcache")}
        r = run("tradeoff", "--scene", "default", "--size", "32x18", "--sweep", "ssao.samples=4,8", "--metric", "rms",
                "--buffer", "ao", "--ao-rays", "8", "--frames", "1", "--warmup", "0", "--quiet", "--csv",
                os.path.join(self.tmp.name, "seed-t.csv"), "--record", record, env=env, timeout=600)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(record) as f:
            d = json.load(f)
        self.assertEqual(d["seeds"]["reference"], "1")
        r = run("replay", record, env=env, timeout=600)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertEqual(len(re.findall(r"^point \d camera 0, ssao\.samples=\d: rms \S+ -> \S+ \(same\)", r.stdout, re.M)),
                         2, r.stdout)
        # Another seed traces another reference: every error differs (the seed is used, not only kept).
        seeded = os.path.join(self.tmp.name, "seed-t2.json")
        d["seeds"]["reference"] = "2"
        with open(seeded, "w") as f:
            json.dump(d, f)
        r = run("replay", seeded, env=env, timeout=600)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertEqual(len(re.findall(r"\(differs\);", r.stdout)), 2, r.stdout)
        self.assertIn("tradeoff: differs (2 row(s) with another error", r.stdout)
        # --diff of the two records names the seed.
        r = run("replay", "--diff", record, seeded)
        self.assertIn("seed reference: 1 -> 2", r.stdout.splitlines())

    def test_a_render_of_a_reference_buffer_records_its_rays_seed_and_spp_and_replays_with_them(self):
        record = os.path.join(self.tmp.name, "ref.json")
        env = {"DW_REFERENCE_CACHE": os.path.join(self.tmp.name, "refcache-render")}
        r = run("render", "--scene", "default", "--size", "32x18", "--buffer", "reference.ao", "--ao-rays", "8", "--seed",
                "3", "--spp", "2", "--out", os.path.join(self.tmp.name, "ref.exr"), "--record", record, env=env, timeout=600)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(record) as f:
            d = json.load(f)
        self.assertEqual((d["buffer"], d["reference"], d["seeds"]["reference"]),
                         ("reference.ao", {"ao_rays": 8, "spp": 2, "filter": "box"}, "3"))
        r = run("replay", record, env=env, timeout=600)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertTrue(r.stdout.endswith("inputs changed: none\nimage: identical\n"), r.stdout)
        # A record from before --spp was kept reads as 1 sample: another image (the samples are used, not only kept).
        older = dict(d, reference={"ao_rays": 8})
        before = os.path.join(self.tmp.name, "ref-before-spp.json")
        with open(before, "w") as f:
            json.dump(older, f)
        r = run("replay", before, env=env, timeout=600)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("image: differs", r.stdout)
        # Another seed traces another AO pattern: the image differs (the seed is used, not only kept).
        d["seeds"]["reference"] = "4"
        other = os.path.join(self.tmp.name, "ref4.json")
        with open(other, "w") as f:
            json.dump(d, f)
        r = run("replay", other, env=env, timeout=600)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("image: differs", r.stdout)
        d["seeds"]["reference"] = "4294967295"
        with open(other, "w") as f:
            json.dump(d, f)
        r = run("replay", other, env=env)
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("seeds.reference: 4294967295 is outside --seed's range 0..2147483647", r.stderr)

    def test_zero_ms_medians_print_no_ratio(self):
        # Series whose recorded frames are all 0 ms (a pass the timer saw no
        # time in): no ratio, no inf or nan, and never "too few frames".
        def change(d):
            for s in d["results"]["timings"]:
                if s["name"] in ("ao", "tonemap"):
                    s["gpu_ms"] = [0.0] * len(s["gpu_ms"])
        r = run("replay", self.variant("zero.json", change))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        for name in ("ao", "tonemap"):
            line = next(l for l in r.stdout.splitlines() if re.match(r"timing %s +gpu" % name, l))
            self.assertRegex(line, r"gpu median +0\.000 -> +[0-9.]+ ms  n/a \(0 ms\)$")
        self.assertNotRegex(r.stdout.lower(), r"\binf\b|\bnan\b")
        self.assertNotIn("too few frames", r.stdout)


    def test_bench_record_flag_and_a_record_cut_short(self):
        # bench --record FILE writes the record (--json is its older name); replay accepts it.
        record = os.path.join(self.tmp.name, "br.json")
        r = run("bench", "--scene", self.scene, "--size", "32x18", "--sweep", "ssao.samples=4,8,16,32,64", "--frames", "2",
                "--warmup", "0", "--no-lpp", "--quiet", "--csv", os.path.join(self.tmp.name, "br.csv"), "--record", record)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(record) as f:
            d = json.load(f)
        self.assertEqual((d["format"], d["command"]), ("deferred-workbench record", "bench"))
        self.assertIn("ssao/ssao.frag", [f["path"] for f in d["shaders"]["files"]])
        r = run("replay", record)
        self.assertIn(r.returncode, (0, 1), r.stdout + r.stderr)
        self.assertEqual(len(re.findall(r"^config \d \(32x18, \d+ lights, ssao\.samples=\d+\): frame gpu median", r.stdout,
                                        re.M)), 5, r.stdout)
        self.assertNotIn("shader file", r.stdout)
        self.assertIn("inputs changed: none", r.stdout)
        # --record and --json naming two files: refused, both named.
        r = run("bench", "--scene", self.scene, "--size", "32x18", "--frames", "1", "--record", "a.json", "--json", "b.json")
        self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
        self.assertIn("--record and --json are one option", r.stderr)
        # Cut short: the results lack configurations 1..4 of the sweep it declares, and config 0's
        # frames are 0 ms: the summary names the missing ones, the 0 ms median has no ratio.
        def cut(d):
            d["results"]["configs"] = d["results"]["configs"][:1]
            for s in d["results"]["configs"][0]["samples"]:
                s["gpu_ms"]["frame"] = 0.0
        r = run("replay", self.variant("cut.json", lambda x: (x.update(d), cut(x))))
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertRegex(r.stdout, r"config 0 \(32x18, \d+ lights, ssao\.samples=4\): frame gpu median +0\.000 -> +[0-9.]+ ms  n/a \(0 ms\)")
        summary = r.stdout.strip().splitlines()[-1]
        self.assertRegex(summary, r"^bench: differs \(4 configuration\(s\) not in the record: config 1 \(32x18, \d+ lights, "
                                  r"ssao\.samples=8\), config 2 \(.*ssao\.samples=16\), config 3 \(.*ssao\.samples=32\) and 1 more; ")


if __name__ == "__main__":
    unittest.main()
