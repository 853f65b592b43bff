#!/usr/bin/env python3
"""Plots a `deferred-workbench bench` samples CSV: median frame GPU ms against
the light count, one line per configuration of the other axes (strategy,
size, ...), log-log. `bench --plot FILE.png` runs it; it can be run by hand:

    python3 scripts/bench_plot.py --csv bench.csv --out bench.png [--size 800x500] [--cpu]

Exit codes: 0 drawn, 2 bad arguments or CSV, 3 matplotlib is missing
(Debian: apt-get install python3-matplotlib).
"""
import argparse
import csv
import random
import statistics
import sys

# Columns that are not configuration axes (docs/bench.md, "The samples CSV").
SAMPLE_COLUMNS = ["lpp", "lpp_lit", "sample", "seq", "frame", "pass", "gpu_ms", "cpu_ms"]
# The cost counters, after them when the run counted them.
COUNTER_COLUMNS = ["fragments", "samples", "primitives", "vertices", "compute", "bytes"]
# Each frame's peak GPU memory, after cpu_ms (before the counters); older CSVs lack it.
MEMORY_COLUMN = "gpu_mem_peak_mib"


def median_interval(ms, resamples=1000):
    """The 95% percentile bootstrap interval of the median of `ms` (seeded: the same samples, the same bars)."""
    rng = random.Random(12345)
    medians = sorted(statistics.median(rng.choices(ms, k=len(ms))) for _ in range(resamples))
    return medians[int(0.025 * (resamples - 1))], medians[int(round(0.975 * (resamples - 1)))]


def read_medians(path, column):
    """{(axis values except lights): {lights: median}} and the axis names."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        timed = header[:-len(COUNTER_COLUMNS)] if header and header[-len(COUNTER_COLUMNS):] == COUNTER_COLUMNS else header
        if timed and timed[-1] == MEMORY_COLUMN:
            timed = timed[:-1]
        if not timed or timed[:3] != ["config", "size", "lights"] or timed[-len(SAMPLE_COLUMNS):] != SAMPLE_COLUMNS:
            raise ValueError(f"{path}: not a bench samples CSV (header {header})")
        axes = timed[1:len(timed) - len(SAMPLE_COLUMNS)]  # size, lights, knobs...
        index = {name: i for i, name in enumerate(header)}
        times = {}  # config -> (axis values, [ms])
        for row in reader:
            if not row or row[index["pass"]] != "frame" or row[index[column]] == "":
                continue
            config = int(row[0])
            values = tuple(row[index[a]] for a in axes)
            times.setdefault(config, (values, []))[1].append(float(row[index[column]]))
    lights_at = axes.index("lights")
    others = [a for a in axes if a != "lights"]
    # Only the axes that vary name the lines.
    varying = [a for a in others if len({v[axes.index(a)] for v, _ in times.values()}) > 1]
    lines = {}
    for config in sorted(times):
        values, ms = times[config]
        label = ", ".join(values[axes.index(a)] for a in varying) or "all"
        lines.setdefault(label, {})[int(values[lights_at])] = statistics.median(ms)
        INTERVALS.setdefault(label, {})[int(values[lights_at])] = median_interval(ms)
    return lines, ", ".join(varying)


INTERVALS = {}  # label -> lights -> (low, high) of the median, filled by read_medians


def error_bars(label, xs, medians):
    """Asymmetric error bars (below, above) of the medians at the light counts xs."""
    lo = [max(0.0, m - INTERVALS[label][n][0]) for n, m in zip(xs, medians)]
    hi = [max(0.0, INTERVALS[label][n][1] - m) for n, m in zip(xs, medians)]
    return [lo, hi]


def save(fig, path, dpi):
    """Writes the figure as a PNG of exactly its size; False (after one line) when it cannot."""
    try:
        # No bbox_inches="tight": the image is exactly the size asked for.
        fig.savefig(path, dpi=dpi, format="png")
    except OSError as e:
        print(f"bench_plot: {path}: cannot write the plot: {e.strerror or e}", file=sys.stderr)
        return False
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", default="800x500", help="WIDTHxHEIGHT in pixels")
    parser.add_argument("--cpu", action="store_true", help="plot CPU ms instead of GPU ms")
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    try:
        width, height = (int(v) for v in args.size.lower().split("x"))
        if width < 50 or height < 50:
            raise ValueError
    except ValueError:
        print(f"bench_plot: --size expects WIDTHxHEIGHT of at least 50x50, got '{args.size}'", file=sys.stderr)
        return 2
    column = "cpu_ms" if args.cpu else "gpu_ms"
    try:
        lines, legend_title = read_medians(args.csv, column)
    except (OSError, ValueError, KeyError) as e:
        print(f"bench_plot: {e}", file=sys.stderr)
        return 2
    if not any(n > 0 for points in lines.values() for n in points):
        print(f"bench_plot: nothing to plot in {args.csv}: every row has 0 lights, and the light axis is "
              "logarithmic (run with --lights above 0)", file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.ticker
    except ImportError:
        print("bench_plot: matplotlib is missing (Debian: apt-get install python3-matplotlib)", file=sys.stderr)
        return 3

    dpi = 100
    # Text scales with the image, so a small plot stays legible.
    scale = min(width / 800, height / 500)
    matplotlib.rcParams["font.size"] = max(5.0, min(11.0, 10.0 * scale))
    fig = plt.figure(figsize=(width / dpi, height / dpi), dpi=dpi)
    ax = fig.add_subplot(1, 1, 1)
    skipped = 0
    counts = sorted({n for points in lines.values() for n in points if n > 0})
    if len(counts) == 1:
        # One light count: a line against the light count would be a column
        # of points over a single tick, so a bar per configuration instead.
        labels = [label for label in lines if counts[0] in lines[label]]
        values = [lines[label][counts[0]] for label in labels]
        bars = [error_bars(label, [counts[0]], [v]) for label, v in zip(labels, values)]
        ax.bar(range(len(labels)), values, color=[f"C{i % 10}" for i in range(len(labels))],
               yerr=[[b[0][0] for b in bars], [b[1][0] for b in bars]], capsize=3)
        ax.set_xticks(range(len(labels)))
        ax.set_xticklabels(labels, rotation=30 if len(labels) > 3 else 0, ha="right" if len(labels) > 3 else "center")
        ax.set_xlabel(legend_title or "configuration")
        ax.set_ylabel(f"frame {'CPU' if args.cpu else 'GPU'} ms (median, 95% CI)")
        ax.set_title(args.title or f"frame time at {counts[0]} lights")
        ax.grid(True, axis="y", alpha=0.3)
        fig.tight_layout()
        if not save(fig, args.out, dpi):
            return 2
        print(f"bench_plot: one light count ({counts[0]}): a bar per configuration", file=sys.stderr)
        return 0
    for label, points in lines.items():
        xs = sorted(n for n in points if n > 0)  # a log axis has no 0
        skipped += len(points) - len(xs)
        medians = [points[n] for n in xs]
        ax.errorbar(xs, medians, yerr=error_bars(label, xs, medians), marker="o", label=label, capsize=3,
                    markersize=max(2.0, 6.0 * scale), linewidth=max(0.8, 1.5 * scale))
    ax.set_xscale("log")
    ax.set_yscale("log")
    plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    ax.xaxis.set_major_formatter(plain)
    ax.yaxis.set_major_formatter(plain)
    ax.yaxis.set_minor_formatter(plain)
    values = [v for points in lines.values() for v in points.values() if v > 0]
    if values and max(values) / min(values) > 10:
        ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())  # decades are labelled enough
    ax.set_xlabel("lights")
    ax.set_ylabel(f"frame {'CPU' if args.cpu else 'GPU'} ms (median, 95% CI)")
    ax.set_title(args.title or "frame time against light count")
    ax.grid(True, which="both", alpha=0.3)
    if lines:
        ax.legend(title=legend_title or None, fontsize="small", title_fontsize="small")
    fig.tight_layout()
    if not save(fig, args.out, dpi):
        return 2
    if skipped:
        print(f"bench_plot: left out {skipped} point(s) with 0 lights (log axis)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
