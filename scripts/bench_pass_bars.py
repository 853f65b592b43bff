#!/usr/bin/env python3
"""Bars of chosen passes' GPU medians per configuration of a `bench --json`
file, one group of bars per size, stacked by pass: for studies whose answer
is a pass's cost (seed 000 tables 6.2 and 6.6 in docs/tradeoffs.md).

    python3 scripts/bench_pass_bars.py --json bench.json --passes ao,ao_filter --out bars.png \
        [--label ssao.resolution,ssao.samples] [--names quarter/8=SSAO1,...] [--title T] [--log]

--label: the knobs that name a configuration (default: every swept knob);
--names: replaces a label (the knob values joined by '/') with a name.
Exit codes: 0 drawn, 2 bad arguments or JSON, 3 matplotlib is missing.
"""
import argparse
import json
import sys


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--json", required=True)
    p.add_argument("--passes", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--label", default="")
    p.add_argument("--names", default="")
    p.add_argument("--title", default="")
    p.add_argument("--log", action="store_true")
    a = p.parse_args()
    try:
        configs = json.load(open(a.json))["results"]["configs"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"bench_pass_bars: {a.json}: not a bench JSON ({e})", file=sys.stderr)
        return 2
    passes = a.passes.split(",")
    names = dict(kv.split("=", 1) for kv in a.names.split(",") if kv)
    sizes, labels, ms = [], [], {}
    for c in configs:
        keys = a.label.split(",") if a.label else list(c["knobs"])
        label = "/".join(c["knobs"][k] for k in keys)
        label = names.get(label, label)
        if c["size"] not in sizes:
            sizes.append(c["size"])
        if label not in labels:
            labels.append(label)
        ms[(c["size"], label)] = [c["series"].get(q, {}).get("gpu_ms", {}).get("median", 0.0) for q in passes]
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("bench_pass_bars: matplotlib is missing (apt-get install python3-matplotlib)", file=sys.stderr)
        return 3
    fig, ax = plt.subplots(figsize=(8, 4.2), dpi=100)
    width = 0.8 / len(labels)
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red"]
    for j, label in enumerate(labels):
        for i, size in enumerate(sizes):
            bottom = 0.0
            for k, value in enumerate(ms.get((size, label), [0.0] * len(passes))):
                ax.bar(i + (j - (len(labels) - 1) / 2) * width, value, width * 0.9, bottom=bottom,
                       color=colours[k % len(colours)], alpha=0.4 + 0.6 * (j + 1) / len(labels),
                       label=passes[k] if (i == 0 and j == 0) else None)
                bottom += value
            if i == len(sizes) - 1 or True:
                ax.annotate(label, (i + (j - (len(labels) - 1) / 2) * width, bottom), fontsize=6, ha="center",
                            va="bottom", rotation=90)
    ax.set_xticks(range(len(sizes)))
    ax.set_xticklabels(sizes)
    if a.log:
        ax.set_yscale("log")
    ax.set_ylabel("GPU ms, median per pass (llvmpipe, loaded machine)")
    ax.set_title(a.title, fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, axis="y", lw=0.3)
    fig.tight_layout()
    fig.savefig(a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
