#!/usr/bin/env python3
"""Plots a `deferred-workbench tradeoff` CSV: median GPU frame ms against the
error, both with their 95% intervals, the Pareto front highlighted and each
point on it labelled with its settings. The points are drawn by the CSV's
`front` column: on the front and told apart from every other front point
(filled red), on the front but tied with another point on an axis (hollow
red: tied_with), indistinguishable (off the front, not confidently dominated:
orange squares) and dominated (grey). --time names the x axis: frame, a pass
or a sum of passes (the CSV's time_ms with its interval when its `time`
column names it). With several cameras the rows over
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
        if not header or header[0] != "point" or "camera" not in header or "pareto" not in header:
            raise ValueError(f"{path}: not a tradeoff CSV (header {header})")
        camera = header.index("camera")
        axes = header[1:camera]
        if header[camera + 1:camera + 1 + len(MIDDLE)] != MIDDLE:
            raise ValueError(f"{path}: not a tradeoff CSV (columns after camera: {header[camera + 1:]})")
        index = {name: i for i, name in enumerate(header)}
        rows = []
        for row in reader:
            if not row:
                continue
            rows.append(read_row(row, index, axes, camera, time, path, cost))
    return axes, rows


def time_columns(row, index, time, path):
    """The x axis's columns: time_ms with its interval when the CSV's time is --time's, else frame_gpu_ms or a
    pass's median (no interval)."""
    if "time" in index and row[index["time"]] == time:
        return "time_ms", "time_ms_lo", "time_ms_hi"
    if time == "frame":
        return "frame_gpu_ms", "frame_gpu_ms_lo", "frame_gpu_ms_hi"
    ms = "gpu_ms." + time
    if ms not in index:
        raise ValueError(f"{path}: no column {ms} (--time {time})")
    return ms, ms, ms


def counter_columns(index, time, cost, path):
    """--cost COUNTER: the counter's columns of --time's span (the frame's, a pass's, or each term's of a sum)."""
    names = [cost] if time == "frame" else [f"{cost}.{term}" for term in time.split("+")]
    missing = [n for n in names if n not in index]
    if missing:
        raise ValueError(f"{path}: no column {missing[0]} (--time {time}, --cost {cost}: written without counters?)")
    return names


def read_row(row, index, axes, camera, time, path, cost="gpu_ms"):
    if cost == "gpu_ms":
        ms, ms_lo, ms_hi = time_columns(row, index, time, path)
        x, x_lo, x_hi = (number(row[index[c]]) for c in (ms, ms_lo, ms_hi))
    else:  # a counter: exact, its interval is the value itself
        x = sum(number(row[index[c]]) for c in counter_columns(index, time, cost, path))
        x_lo = x_hi = x
    pareto = row[index["pareto"]] == "1"
    front = row[index["front"]] if "front" in index else ("pareto" if pareto else "")
    return {
        "point": int(row[0]),
        "values": row[1:camera],
        "camera": row[camera],
        "metric": row[index["metric"]],
        "buffer": row[index["buffer"]],
        "error": number(row[index["error"]]),
        "lo": number(row[index["error_lo"]]),
        "hi": number(row[index["error_hi"]]),
        "ms": x,
        "ms_lo": x_lo,
        "ms_hi": x_hi,
        "pareto": pareto,
        "front": front,
        "tied": row[index["tied_with"]] if "tied_with" in index else "",
        "pick": row[index["pick"]] if "pick" in index else "",
    }


# How each class of point is drawn: (label, marker, colour, error-bar colour, filled, size, z).
CLASSES = [
    ("dominated", "dominated (confidently)", ".", "tab:gray", "lightgray", True, 5, 2),
    ("indistinguishable", "indistinguishable (off the front, not confidently dominated)", "s", "tab:orange",
     "navajowhite", False, 6, 2),
    ("tied", "Pareto front, tied with another point", "o", "tab:red", "lightcoral", False, 7, 3),
    ("pareto", "Pareto front, told apart", "o", "tab:red", "tab:red", True, 7, 3),
]


def point_class(r):
    if r["front"] == "pareto" or (not r["front"] and r["pareto"]):
        return "tied" if r["tied"] else "pareto"
    return r["front"] or "dominated"


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


def bars(rows):
    """Both error bars' extents of `rows` (xerr, yerr), 0 where an end is missing."""
    def extent(a, b):
        return max(0.0, a - b) if math.isfinite(a) and math.isfinite(b) else 0.0
    return ([[extent(r["ms"], r["ms_lo"]) for r in rows], [extent(r["ms_hi"], r["ms"]) for r in rows]],
            [[extent(r["error"], r["lo"]) for r in rows], [extent(r["hi"], r["error"]) for r in rows]])


def draw_classes(ax, shown):
    """The points by their front class (CLASSES), with both intervals, and the budget's pick."""
    for key, name, marker, colour, ecolour, filled, size, z in CLASSES:
        group = [r for r in shown if point_class(r) == key]
        if not group:
            continue
        xerr, yerr = bars(group)
        ax.errorbar([r["ms"] for r in group], [r["error"] for r in group], xerr=xerr, yerr=yerr,
                    fmt=marker, color=colour, ecolor=ecolour, capsize=3, markersize=size,
                    markerfacecolor=colour if filled else "white", label=name, zorder=z)
    picked = [r for r in shown if r["pick"] == "pick"]
    if picked:
        ax.plot([r["ms"] for r in picked], [r["error"] for r in picked], "*", color="tab:green", markersize=14,
                label="budget pick", zorder=5)


def error_ties_note(shown):
    """A line under the plot when no two shown points can be told apart in error (their tied_with)."""
    if len(shown) < 2 or not all("tied" in r for r in shown):
        return None
    points = {r["point"] for r in shown}
    for r in shown:
        tied = {int(t.split(":")[0]) for t in r["tied"].split() if t.split(":")[1] in ("error", "both")}
        if r["front"] == "dominated" or tied != points - {r["point"]}:
            return None
    return "no two of these points can be told apart in error (tied_with)"


def draw_overlays(ax, args, overlays, infinite_at, labels):
    """Each --overlay CSV's points as labelled diamonds; returns their (ms, error)."""
    overlay_points = []
    for k, (o_axes, o_rows) in enumerate(overlays):
        o_points = shown_rows(o_rows)
        for r in o_points:
            if r["error"] == math.inf:
                r["error"], r["lo"], r["hi"] = infinite_at, math.nan, math.nan
        if not o_points:
            continue
        o_vary = [i for i, _ in enumerate(o_axes) if len({r["values"][i] for r in o_points}) > 1]
        xerr, yerr = bars(o_points)
        ax.errorbar([r["ms"] for r in o_points], [r["error"] for r in o_points], xerr=xerr, yerr=yerr,
                    fmt="D", color=f"C{k}", ecolor=f"C{k}", alpha=0.8, capsize=3, markersize=6,
                    label=args.overlay[k].rsplit("/", 1)[-1], zorder=4)
        for r in o_points:
            text = ", ".join(r["values"][i] if o_axes[i] == "preset" else f"{o_axes[i]}={r['values'][i]}" for i in o_vary)
            labels.append((r["ms"], r["error"], text or f"point {r['point']}", f"C{k}"))
        overlay_points += [(r["ms"], r["error"]) for r in o_points]
    return overlay_points


def x_label(time, shown, cost="gpu_ms"):
    if cost != "gpu_ms":
        return f"{cost} per frame (exact)" if time == "frame" else f"{cost} of {time} (exact)"
    if time == "frame":
        return "GPU frame ms (median, 95% CI)"
    interval = ", 95% CI" if any(math.isfinite(r["ms_lo"]) and r["ms_lo"] != r["ms"] for r in shown) else ""
    if "+" in time:
        return f"GPU ms of {time} (median of the per-frame sums{interval})"
    return f"GPU ms of the {time} pass (median{interval})"


def read_inputs(args):
    """The size, the CSV and the overlays; None (and one line on stderr) when any is bad."""
    try:
        width, height = (int(v) for v in args.size.split("x"))
        axes, rows = read(args.csv, args.time, args.cost)
        overlays = [read(path, args.time, args.cost) for path in args.overlay]
    except (ValueError, OSError) as e:
        print(f"tradeoff_plot: {e}", file=sys.stderr)
        return None
    return width, height, axes, rows, overlays


def draw(plt, args, inputs):
    """The figure: the classes, the front joined and labelled, the overlays, the axes' names; returns it."""
    width, height, axes, rows, overlays = inputs
    shown = shown_rows(rows)
    infinite_at = place_infinite([shown] + [shown_rows(o_rows) for _, o_rows in overlays])
    # Only the axes that vary name the points.
    varying = [i for i, _ in enumerate(axes) if len({tuple([r["values"][i]]) for r in shown}) > 1]

    # tradeoff --study: a point is its study's name and the knobs that vary within that study.
    study = axes.index("study") if "study" in axes else None
    within = {}
    if study is not None:
        for name in {r["values"][study] for r in shown}:
            members = [r for r in shown if r["values"][study] == name]
            within[name] = [i for i in varying if i != study and len({r["values"][i] for r in members}) > 1]

    def label(r):
        if study is not None:
            name = r["values"][study]
            parts = [name] + [f"{axes[i]}={r['values'][i]}" for i in within[name]]
        else:
            parts = [f"{axes[i]}={r['values'][i]}" if axes[i] != "preset" else r["values"][i] for i in varying]
        text = ", ".join(parts) if parts else f"point {r['point']}"
        return text + " (PSNR inf)" if r.get("inf") else text

    dpi = 100
    fig, ax = plt.subplots(figsize=(width / dpi, height / dpi), dpi=dpi)
    draw_classes(ax, shown)
    front = sorted((r for r in shown if r["pareto"]), key=lambda r: (r["ms"], r["error"]))
    labels = [(r["ms"], r["error"], label(r), "tab:red") for r in front]
    points = [(r["ms"], r["error"]) for r in shown]
    if front:
        ax.plot([r["ms"] for r in front], [r["error"] for r in front], "-", color="tab:red", alpha=0.5, zorder=1)
    if infinite_at is not None:
        ax.axhline(infinite_at, color="tab:blue", linestyle=":", linewidth=1, zorder=0)
        ax.annotate("PSNR inf (identical image)", xy=(0.01, infinite_at), xycoords=("axes fraction", "data"),
                    xytext=(0, -3), textcoords="offset points", va="top", fontsize=7, color="tab:blue")
    overlay_points = draw_overlays(ax, args, overlays, infinite_at, labels)
    metric = shown[0]["metric"] if shown else "error"
    buffer = shown[0]["buffer"] if shown else "?"
    ax.set_xlabel(x_label(args.time, shown, args.cost))
    ax.set_ylabel(f"{metric} of {buffer} (95% CI)")
    over = " over all cameras" if shown and shown[0]["camera"] == "all" else ""
    against = "GPU time" if args.cost == "gpu_ms" else args.cost
    ax.set_title(f"tradeoff: {metric} of {buffer} against {against}{over}")
    note = error_ties_note(shown)
    if note:
        ax.annotate(note, xy=(0.99, 0.01), xycoords="axes fraction", ha="right", va="bottom", fontsize=7,
                    color="tab:orange")
    ax.grid(True, alpha=0.3)
    if shown:
        ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    # The labels last, once the axes' limits and the layout are final.
    place_labels(ax, fig, labels, points + overlay_points, [[(r["ms"], r["error"]) for r in front]])
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", default="800x600")
    parser.add_argument("--overlay", action="append", default=[], help="another tradeoff CSV drawn over it")
    parser.add_argument("--time", default="frame",
                        help="the x axis: frame (frame_gpu_ms), a pass (gpu_ms.PASS) or the CSV's time (time_ms)")
    parser.add_argument("--cost", default="gpu_ms",
                        help="the x axis' quantity: gpu_ms, or a counter (fragments, samples, ... of --time's span)")
    args = parser.parse_args()
    inputs = read_inputs(args)
    if inputs is None:
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
    fig = draw(plt, args, inputs)
    try:
        fig.savefig(args.out, format="png")
    except OSError as e:  # a full disk, a folder that went away: one line, not a traceback
        print(f"tradeoff_plot: {args.out}: cannot write the plot: {e.strerror or e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
