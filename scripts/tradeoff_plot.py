#!/usr/bin/env python3
"""Plots a `deferred-workbench tradeoff` CSV: median GPU frame ms against the
error, both with their 95% intervals, the Pareto front highlighted and each
point on it labelled with its settings. With several cameras the rows over
all cameras ("all") are drawn. `tradeoff --plot FILE.png` runs it; by hand:

    python3 scripts/tradeoff_plot.py --csv tradeoff.csv --out tradeoff.png [--size 800x600] [--overlay presets.csv]

--overlay draws another tradeoff CSV's points (e.g. presets measured the same
way) over the first, as labelled diamonds.

Labels are placed one by one where they overlap no label placed before, no
point and not the legend, crossing the front's line as little as they can
(place_labels of scripts/plot_labels.py, which
ao_methods_plot.py shares: the nearest free offset around the point, stepping
outwards), with a thin line to a point they had to move away from. The script
imports plot_labels.py from its own folder (installed beside it).

Exit codes: 0 drawn, 2 bad arguments or CSV, 3 matplotlib is missing
(Debian: apt-get install python3-matplotlib), 4 plot_labels.py is not beside
the script.
"""
import argparse
import csv
import math
import sys

try:
    from plot_labels import place_labels  # beside this script (scripts/, share/deferred-workbench/)
except ImportError:
    place_labels = None

MIDDLE = ["metric", "buffer", "error", "error_lo", "error_hi", "frames",
          "frame_gpu_ms", "frame_gpu_ms_lo", "frame_gpu_ms_hi"]


def number(text):
    if text == "":
        return math.nan
    return float(text)


def read(path, time="frame", cost="gpu_ms"):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if not header or header[0] != "point" or "camera" not in header or header[-1] != "pareto":
            raise ValueError(f"{path}: not a tradeoff CSV (header {header})")
        camera = header.index("camera")
        axes = header[1:camera]
        if header[camera + 1:camera + 1 + len(MIDDLE)] != MIDDLE:
            raise ValueError(f"{path}: not a tradeoff CSV (columns after camera: {header[camera + 1:]})")
        index = {name: i for i, name in enumerate(header)}
        # --time PASS: the pass's median on the x axis (no interval in the CSV).
        ms = "frame_gpu_ms" if time == "frame" else "gpu_ms." + time
        if cost != "gpu_ms":  # --cost COUNTER: exact, its interval is the value itself
            ms = cost if time == "frame" else cost + "." + time
        if ms not in index:
            raise ValueError(f"{path}: no column {ms} (--time {time}, --cost {cost})")
        ms_lo = "frame_gpu_ms_lo" if time == "frame" and cost == "gpu_ms" else ms
        ms_hi = "frame_gpu_ms_hi" if time == "frame" and cost == "gpu_ms" else ms
        rows = []
        for row in reader:
            if not row:
                continue
            rows.append({
                "point": int(row[0]),
                "values": row[1:camera],
                "camera": row[camera],
                "metric": row[index["metric"]],
                "buffer": row[index["buffer"]],
                "error": number(row[index["error"]]),
                "lo": number(row[index["error_lo"]]),
                "hi": number(row[index["error_hi"]]),
                "ms": number(row[index[ms]]),
                "ms_lo": number(row[index[ms_lo]]),
                "ms_hi": number(row[index[ms_hi]]),
                "pareto": row[-1] == "1",
            })
    return axes, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", default="800x600")
    parser.add_argument("--overlay", action="append", default=[], help="another tradeoff CSV drawn over it")
    parser.add_argument("--time", default="frame", help="the x axis: frame (frame_gpu_ms) or a pass (gpu_ms.PASS)")
    parser.add_argument("--cost", default="gpu_ms",
                        help="the x axis' quantity: gpu_ms, or a counter (fragments, samples, ... of --time's span)")
    args = parser.parse_args()
    try:
        width, height = (int(v) for v in args.size.split("x"))
        axes, rows = read(args.csv, args.time, args.cost)
        overlays = [read(path, args.time, args.cost) for path in args.overlay]
    except (ValueError, OSError) as e:
        print(f"tradeoff_plot: {e}", file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("tradeoff_plot: matplotlib is missing (Debian: apt-get install python3-matplotlib)", file=sys.stderr)
        return 3
    if place_labels is None:
        print(f"tradeoff_plot: cannot import plot_labels.py, which places the labels; it belongs beside {__file__}",
              file=sys.stderr)
        return 4

    def shown_rows(rows):
        """The all-cameras rows when there are any, else the first camera's; with a time and an error."""
        shown = [r for r in rows if r["camera"] == "all"]
        if not shown:
            cameras = sorted({r["camera"] for r in rows})
            shown = [r for r in rows if r["camera"] == cameras[0]] if cameras else []
        # A PSNR of inf (an image identical to the one measured against) is the best error
        # there is: kept, and drawn at the top (place_infinite).
        return [r for r in shown if math.isfinite(r["ms"])
                and (math.isfinite(r["error"]) or (r["error"] == math.inf and r["metric"] == "psnr"))]

    def place_infinite(groups):
        """Puts the rows with a PSNR of inf at a finite height above every finite one; returns it (None: none)."""
        all_rows = [r for g in groups for r in g]
        if not any(r["error"] == math.inf for r in all_rows):
            return None
        finite = [v for r in all_rows for v in (r["error"], r["lo"], r["hi"]) if math.isfinite(v)]
        top = max(finite) + max(1.0, 0.1 * abs(max(finite))) if finite else 100.0
        for r in all_rows:
            if r["error"] == math.inf:
                r["error"], r["lo"], r["hi"], r["inf"] = top, math.nan, math.nan, True
        return top

    shown = shown_rows(rows)
    infinite_at = place_infinite([shown] + [shown_rows(o_rows) for _, o_rows in overlays])
    # Only the axes that vary name the points.
    varying = [i for i, _ in enumerate(axes) if len({tuple([r["values"][i]]) for r in shown}) > 1]

    def label(r):
        parts = [f"{axes[i]}={r['values'][i]}" if axes[i] != "preset" else r["values"][i] for i in varying]
        text = ", ".join(parts) if parts else f"point {r['point']}"
        return text + " (PSNR inf)" if r.get("inf") else text

    dpi = 100
    fig, ax = plt.subplots(figsize=(width / dpi, height / dpi), dpi=dpi)
    for front in (False, True):
        group = [r for r in shown if r["pareto"] == front]
        if not group:
            continue
        xerr = [[max(0.0, r["ms"] - r["ms_lo"]) if math.isfinite(r["ms_lo"]) else 0.0 for r in group],
                [max(0.0, r["ms_hi"] - r["ms"]) if math.isfinite(r["ms_hi"]) else 0.0 for r in group]]
        yerr = [[max(0.0, r["error"] - r["lo"]) if math.isfinite(r["lo"]) else 0.0 for r in group],
                [max(0.0, r["hi"] - r["error"]) if math.isfinite(r["hi"]) else 0.0 for r in group]]
        ax.errorbar([r["ms"] for r in group], [r["error"] for r in group], xerr=xerr, yerr=yerr,
                    fmt="o" if front else ".", color="tab:red" if front else "tab:gray",
                    ecolor="tab:red" if front else "lightgray", capsize=3, markersize=7 if front else 5,
                    label="Pareto front" if front else "other points", zorder=3 if front else 2)
    front = sorted((r for r in shown if r["pareto"]), key=lambda r: (r["ms"], r["error"]))
    labels = [(r["ms"], r["error"], label(r), "tab:red") for r in front]
    points = [(r["ms"], r["error"]) for r in shown]
    overlay_points = []
    if front:
        ax.plot([r["ms"] for r in front], [r["error"] for r in front], "-", color="tab:red", alpha=0.5, zorder=1)
    if infinite_at is not None:
        ax.axhline(infinite_at, color="tab:blue", linestyle=":", linewidth=1, zorder=0)
        ax.annotate("PSNR inf (identical image)", xy=(0.01, infinite_at), xycoords=("axes fraction", "data"),
                    xytext=(0, -3), textcoords="offset points", va="top", fontsize=7, color="tab:blue")
    for k, (o_axes, o_rows) in enumerate(overlays):
        o_points = shown_rows(o_rows)
        for r in o_points:
            if r["error"] == math.inf:
                r["error"], r["lo"], r["hi"] = infinite_at, math.nan, math.nan
        if not o_points:
            continue
        o_vary = [i for i, _ in enumerate(o_axes) if len({r["values"][i] for r in o_points}) > 1]
        ax.errorbar([r["ms"] for r in o_points], [r["error"] for r in o_points],
                    xerr=[[max(0.0, r["ms"] - r["ms_lo"]) for r in o_points], [max(0.0, r["ms_hi"] - r["ms"]) for r in o_points]],
                    yerr=[[max(0.0, r["error"] - r["lo"]) for r in o_points], [max(0.0, r["hi"] - r["error"]) for r in o_points]],
                    fmt="D", color=f"C{k}", ecolor=f"C{k}", alpha=0.8, capsize=3, markersize=6,
                    label=args.overlay[k].rsplit("/", 1)[-1], zorder=4)
        for r in o_points:
            text = ", ".join(r["values"][i] if o_axes[i] == "preset" else f"{o_axes[i]}={r['values'][i]}" for i in o_vary)
            labels.append((r["ms"], r["error"], text or f"point {r['point']}", f"C{k}"))
        overlay_points += [(r["ms"], r["error"]) for r in o_points]
    metric = shown[0]["metric"] if shown else "error"
    buffer = shown[0]["buffer"] if shown else "?"
    if args.cost != "gpu_ms":
        ax.set_xlabel(f"{args.cost} per frame (exact)" if args.time == "frame" else f"{args.cost} of the {args.time} pass (exact)")
    else:
        ax.set_xlabel("GPU frame ms (median, 95% CI)" if args.time == "frame"
                      else f"GPU ms of the {args.time} pass (median)")
    ax.set_ylabel(f"{metric} of {buffer} (95% CI)")
    over = " over all cameras" if shown and shown[0]["camera"] == "all" else ""
    ax.set_title(f"tradeoff: {metric} of {buffer} against GPU time{over}")
    ax.grid(True, alpha=0.3)
    if shown:
        ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    # The labels last, once the axes' limits and the layout are final.
    place_labels(ax, fig, labels, points + overlay_points, [[(r["ms"], r["error"]) for r in front]])
    try:
        fig.savefig(args.out, format="png")
    except OSError as e:  # a full disk, a folder that went away: one line, not a traceback
        print(f"tradeoff_plot: {args.out}: cannot write the plot: {e.strerror or e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
