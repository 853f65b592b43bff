"""Experiment records (issue 24): `render --record` then `replay`, through the
CLI (DW_WORKBENCH_BINARY). The same record replays to the same image bit for
bit (exit 0); a changed scene file, knob or build field is named; a record
of a newer format version is refused with its version named (exit 2)."""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

BINARY = os.environ["DW_WORKBENCH_BINARY"]
SCENES = os.path.join(os.path.dirname(__file__), "..", "..", "scenes")


def run(*args):
    return subprocess.run([BINARY] + list(args), capture_output=True, text=True)


class RecordTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.scene = os.path.join(cls.tmp.name, "spotlights.json")
        shutil.copy(os.path.join(SCENES, "spotlights.json"), cls.scene)
        cls.record = os.path.join(cls.tmp.name, "r.json")
        r = run("render", "--scene", cls.scene, "--size", "64x36", "--frames", "3", "--warmup", "1", "--set",
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
        self.assertEqual(d["version"], 1)
        self.assertEqual(d["size"], [64, 36])
        self.assertEqual((d["frames"], d["warmup"]), (3, 1))
        self.assertEqual(d["knobs"]["ssao.samples"], "8")
        self.assertEqual(d["scene"]["files"][0]["path"], self.scene)
        self.assertEqual(len(d["scene"]["files"][0]["sha256"]), 64)
        self.assertEqual(len(d["results"]["image"]["sha256"]), 64)
        frame = next(s for s in d["results"]["timings"] if s["name"] == "frame")
        self.assertEqual(len(frame["gpu_ms"]), 3)
        for key in ("version", "commit", "compiler"):
            self.assertIn(key, d["build"])
        self.assertIn("renderer", d["gl"])
        self.assertIn("cpu", d["host"])

    def test_replay_gives_the_same_image(self):
        r = run("replay", self.record)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("image: identical", r.stdout)
        self.assertIn("timing frame", r.stdout)
        self.assertNotIn("changed", r.stdout)

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
        self.assertIn("record version 99 is newer than this build reads (1)", r.stderr)
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


if __name__ == "__main__":
    unittest.main()
