"""The cluster recipes of docs/bench.md and docs/tradeoffs.md run as written
(issue 32): Slurm's --output=logs/... needed a logs/ folder Slurm does not
make, and the Kubernetes recipe wrote to /shared/out, which nothing made.

For each recipe the test takes the job script (Slurm) or the container's
command (Kubernetes) and the merge command from the page itself, runs every
shard of it in an empty temporary folder with the array variable set
(SLURM_ARRAY_TASK_ID 0..N-1 from #SBATCH --array, JOB_COMPLETION_INDEX
0..completions-1), a Kubernetes volume's mountPath standing for a folder
there, then the merge, and compares the merged table with one unsharded run
of the same command: the configurations (sizes, lights, swept values, lights
per pixel, sample counts) for bench, the points, values, cameras and errors
for tradeoff. Times are never compared.

The `deferred-workbench` the scripts find on PATH is a small wrapper that
shrinks what only costs time (--size to 32x18-sized frames, --lights to
1..5, --frames to 2, --orbit to 2 cameras) and runs the build's binary, so the scripts
themselves run unchanged."""
import csv
import glob
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile
import unittest

import yaml

BINARY = os.environ["DW_WORKBENCH_BINARY"]
DOCS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs")

# What the wrapper runs instead of the recipes' sizes, light counts and frames.
WRAPPER = r'''#!/usr/bin/python3
import json, os, sys
SIZES = ["32x18", "48x27", "64x36", "40x22", "56x32"]
args = sys.argv[1:]
out = []
i = 0
while i < len(args):
    a = args[i]
    if a in ("--size", "--lights", "--frames", "--orbit") and i + 1 < len(args) and args[1:2] != ["merge"]:
        n = len(args[i + 1].split(","))
        value = {"--size": ",".join(SIZES[:n]), "--lights": ",".join(str(k + 1) for k in range(n)),
                 "--frames": "2", "--orbit": "2"}[a]
        out += [a, value]
        i += 2
        continue
    out.append(a)
    i += 1
with open(os.environ["DW_RECIPE_LOG"], "a") as log:
    log.write(json.dumps({"cwd": os.getcwd(), "args": out}) + "\n")
os.execv(os.environ["DW_RECIPE_BINARY"], [os.environ["DW_RECIPE_BINARY"]] + out)
'''


def section(page, title):
    """The text of `### title` up to the next heading of level 2 or 3."""
    with open(os.path.join(DOCS, page)) as f:
        text = f.read()
    start = text.index("### " + title + "\n")
    end = re.search(r"^##+ ", text[start + 4:], re.M)
    return text[start: start + 4 + end.start()] if end else text[start:]


def blocks(text, language):
    return re.findall(r"^```" + language + r"\n(.*?)^```", text, re.S | re.M)


class Recipes(unittest.TestCase):
    unsharded = {}

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)
        self.bin = os.path.join(self.tmp.name, "bin")
        os.makedirs(self.bin)
        wrapper = os.path.join(self.bin, "deferred-workbench")
        with open(wrapper, "w") as f:
            f.write(WRAPPER)
        os.chmod(wrapper, 0o755)
        self.log = os.path.join(self.tmp.name, "calls.jsonl")
        self.work = os.path.join(self.tmp.name, "job")  # the empty folder the job starts in
        os.makedirs(self.work)

    def env(self, **extra):
        env = dict(os.environ, PATH=self.bin + os.pathsep + os.environ["PATH"], DW_RECIPE_LOG=self.log,
                   DW_RECIPE_BINARY=BINARY, DW_REFERENCE_CACHE=os.path.join(self.tmp.name, "default-cache"))
        env.update(extra)
        return env

    def sh(self, shell, script, **extra):
        r = subprocess.run([shell, "-c", script], cwd=self.work, env=self.env(**extra), capture_output=True, text=True,
                           timeout=900)
        self.assertEqual(r.returncode, 0, "%s\n%s\n%s" % (script, r.stdout, r.stderr))
        return r

    def calls(self, command):
        with open(self.log) as f:
            return [c for c in map(json.loads, f) if c["args"][:1] == [command] and c["args"][1:2] != ["merge"]]

    def run_unsharded(self, command):
        """The first shard's command without --shard, its outputs in a folder of its own; cached per command."""
        args = self.calls(command)[0]["args"]
        kept, i = [], 0
        while i < len(args):
            if args[i] in ("--shard", "--csv", "--json", "--plot", "--record"):
                i += 2
                continue
            kept.append(args[i])
            i += 1
        key = json.dumps(kept)
        if key not in Recipes.unsharded:
            folder = tempfile.mkdtemp(prefix="unsharded-", dir=os.path.dirname(self.tmp.name))
            self.addCleanup(subprocess.run, ["rm", "-rf", folder])
            out = os.path.join(folder, "all.csv")
            r = subprocess.run([BINARY] + kept + ["--csv", out], cwd=folder, capture_output=True, text=True, timeout=900,
                               env=dict(os.environ, DW_REFERENCE_CACHE=os.path.join(folder, "cache")))
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            with open(out) as f:
                Recipes.unsharded[key] = list(csv.DictReader(f))
        return Recipes.unsharded[key]

    # --- what is compared ---------------------------------------------------
    def bench_table(self, rows):
        """Per configuration: size, lights, swept values, lights per pixel, how many rows (samples x series), and
        each series' cost counters (per pass, exact: the same in a shard as unsharded)."""
        counters = ("fragments", "samples", "primitives", "vertices", "compute", "bytes")
        # gpu_mem_peak_mib: a shard's can differ by what growth-only buffers kept from earlier configurations.
        fixed = {"sample", "seq", "frame", "pass", "gpu_ms", "cpu_ms", "gpu_mem_peak_mib", *counters}
        table = {}
        for r in rows:
            key = r["config"]
            desc = tuple(sorted((k, v) for k, v in r.items() if k not in fixed))
            entry = table.setdefault(key, [desc, 0, set()])
            self.assertEqual(entry[0], desc, "config %s changes its description between rows" % key)
            entry[1] += 1
            entry[2].add((r["pass"],) + tuple(r.get(c, "") for c in counters))
        return table

    def tradeoff_table(self, rows):
        # The times, and what is decided from them (the front, its classes and ties: a merge decides them from the
        # intervals, a single run from its resamples) differ between runs; the points, values and errors do not.
        # The peak GPU memory depends on the points rendered before in the same process (growth-only buffers keep
        # their largest size): a shard's can differ from the unsharded run's by those bytes (docs/bench.md).
        timed = ("frame_gpu_ms", "frame_gpu_ms_lo", "frame_gpu_ms_hi", "pareto", "time_ms", "time_ms_lo", "time_ms_hi",
                 "front", "dominated_by", "tied_with", "pick", "gpu_mem_peak_mib")
        cols = [c for c in rows[0] if c not in timed and not c.endswith("_gpu_ms") and not c.startswith("gpu_ms")]
        return sorted(tuple(r[c] for c in cols) for r in rows), cols

    def compare(self, command, merged_csv):
        with open(merged_csv) as f:
            merged = list(csv.DictReader(f))
        unsharded = self.run_unsharded(command)
        self.assertGreater(len(merged), 0)
        if command == "bench":
            table = self.bench_table(merged)
            self.assertEqual(len(table), 45)  # 3 sizes x 5 light counts x 3 strategies, each once
            self.assertEqual(table, self.bench_table(unsharded))
        else:
            self.assertEqual(self.tradeoff_table(merged), self.tradeoff_table(unsharded))

    # --- the recipes ------------------------------------------------------
    def slurm(self, page, command):
        text = section(page, "Slurm job array")
        script, submit = blocks(text, "bash")[:2]
        self.assertNotIn("--output=logs/", script)
        array = re.search(r"^#SBATCH --array=(\d+)-(\d+)", script, re.M)
        self.assertIsNotNone(array, script)
        # Slurm opens the log before the script runs: its folder must exist in the empty folder.
        log = re.search(r"^#SBATCH --output=(\S+)", script, re.M).group(1)
        self.assertEqual(os.path.dirname(log), "", "the log %s is in a folder the empty job folder lacks" % log)
        with open(os.path.join(self.work, page.replace(".md", ".sbatch")), "w") as f:
            f.write(script)
        shards = range(int(array.group(1)), int(array.group(2)) + 1)
        for i in shards:
            self.sh("bash", script, SLURM_ARRAY_TASK_ID=str(i), SLURM_ARRAY_JOB_ID="1", SLURM_SUBMIT_DIR=self.work)
        self.assertEqual(len(self.calls(command)), len(shards))
        merge = re.search(r'--wrap\s*\\?\s*"([^"]+)"', submit).group(1)
        self.sh("sh", merge)
        return merge

    def kubernetes(self, page, command):
        text = section(page, "Kubernetes Indexed Job")
        job = yaml.safe_load(blocks(text, "yaml")[0])
        merge = blocks(text, "sh")[0].strip()
        spec = job["spec"]
        container = spec["template"]["spec"]["containers"][0]
        self.assertEqual(container["command"], ["/bin/sh", "-c"])
        script = container["args"][0]
        env = {e["name"]: e["value"] for e in container.get("env", [])}
        # Each volume's mountPath stands for a folder that exists (the volume), empty at first.
        for mount in container.get("volumeMounts", []):
            folder = os.path.join(self.tmp.name, "volume-" + mount["name"])
            os.makedirs(folder)
            script = script.replace(mount["mountPath"] + "/", folder + "/")
            merge = merge.replace(mount["mountPath"] + "/", folder + "/")
            env = {k: v.replace(mount["mountPath"] + "/", folder + "/") for k, v in env.items()}
            self.assertNotIn(mount["mountPath"] + "/", script)
        for i in range(spec["completions"]):
            self.sh("/bin/sh", script, JOB_COMPLETION_INDEX=str(i), **env)
        self.assertEqual(len(self.calls(command)), spec["completions"])
        self.sh("sh", merge)
        return merge

    def merged_csv(self, merge):
        out = shlex.split(merge)[shlex.split(merge).index("--out") + 1]
        return out if os.path.isabs(out) else os.path.join(self.work, out)

    def test_bench_slurm_recipe(self):
        merge = self.slurm("bench.md", "bench")
        self.compare("bench", self.merged_csv(merge))
        self.assertEqual(len(glob.glob(os.path.join(self.work, "results", "shard-*.json"))), 8)
        self.assertTrue(os.path.isfile(os.path.join(self.work, "results", "all.png")))

    def test_bench_kubernetes_recipe(self):
        merge = self.kubernetes("bench.md", "bench")
        self.compare("bench", self.merged_csv(merge))

    def test_tradeoff_slurm_recipe(self):
        merge = self.slurm("tradeoffs.md", "tradeoff")
        self.compare("tradeoff", self.merged_csv(merge))
        # The shards shared the cache the script names (in the job's folder).
        self.assertTrue(os.listdir(os.path.join(self.work, "dw-reference")))

    def test_tradeoff_kubernetes_recipe(self):
        merge = self.kubernetes("tradeoffs.md", "tradeoff")
        self.compare("tradeoff", self.merged_csv(merge))
        self.assertTrue(os.listdir(os.path.join(self.tmp.name, "volume-shared", "dw-reference")))


if __name__ == "__main__":
    unittest.main()
