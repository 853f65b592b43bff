#!/usr/bin/env python3
"""Puts several `deferred-workbench tradeoff` CSVs of the AO methods (one per
`ao.method`, each its own sweep) on one plot: the AO passes' GPU ms
(`gpu_ms.ao` + `gpu_ms.ao_filter`, the columns the tradeoff CSV has per
pass) against the error, each method in its colour, and the Pareto front
over all of them. On a loaded machine the frame time is mostly the other
passes' noise; the AO passes' own medians rank the methods. It prints a
Markdown table of the joint front and, for a target error (by default the
one SSAO reaches at 16 samples, half size), the cheapest point of each
method at or below it.

    python3 scripts/ao_methods_plot.py --out ao.png ssao=a.csv gtao=b.csv aov=c.csv \
        [--target-method ssao --target ssao.samples=16,ssao.resolution=half] [--only aov.radius=1] [--title T] \
        [--errors ssao=a-flip-ao.csv ...] [--plot-error flip:ao]

--errors METHOD=FILE.csv (repeatable): another tradeoff CSV of the same sweep
measuring another error (e.g. `--metric flip --buffer final` with `--frames 1`);
each point keeps the time of the METHOD=FILE.csv it came from (the timed run)
and gains this error, matched by the sweep's values. With any --errors the
script prints, per method, a table of every point's AO ms and all its errors
(one column per metric and buffer). --plot-error METRIC:BUFFER (e.g. flip:final)
puts that error on the plot, the front and the target table instead of the
main CSV's; a point without that error is left out.

The front's points are labelled with their settings' values, each label
where it covers no point, no other label and not the legend, crossing the
front's line and the target's as little as it can (place_labels of
scripts/plot_labels.py, shared with tradeoff_plot.py; a label moved away from
its point gets a thin line to it).

Rows: the `all` camera rows when there are several cameras, else camera 0.
Exit codes: 0 drawn, 2 bad arguments or CSV, 3 matplotlib is missing, 4
plot_labels.py is not beside the script.
"""
import argparse
import csv
import math
import sys

try:
    from plot_labels import place_labels  # beside this script (scripts/, share/deferred-workbench/)
except ImportError:
    place_labels = None

PASSES = ["gpu_ms.ao", "gpu_ms.ao_filter"]


def number(text):
    return math.nan if text in ("", None) else float(text)


def read(label, path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or "camera" not in rows[0] or "error" not in rows[0]:
        raise ValueError(f"{path}: not a tradeoff CSV")
    header = list(rows[0].keys())
    axes = header[1:header.index("camera")]
    cams = {r["camera"] for r in rows}
    want = "all" if "all" in cams else "0"
    points = []
    for r in rows:
        if r["camera"] != want:
            continue
        ms = sum(number(r.get(p, "")) if r.get(p, "") != "" else 0.0 for p in PASSES)
        points.append({
            "method": label,
            "settings": ",".join(f"{a}={r[a]}" for a in axes),
            "values": {a: r[a] for a in axes},
            "error": number(r["error"]),
            "ao_ms": ms,
            "frame_ms": number(r["frame_gpu_ms"]),
            "metric": r["metric"],
            "buffer": r["buffer"],
        })
    return points


def read_errors(path):
    """A tradeoff CSV as {settings: error} (the same rows as read), with its metric and buffer."""
    points = read("", path)
    if not points:
        raise ValueError(f"{path}: no rows")
    return f'{points[0]["metric"]}:{points[0]["buffer"]}', {p["settings"]: p["error"] for p in points}


def front(points):
    """Points no other point beats: at most as slow and as wrong, better in one."""
    out = []
    for p in points:
        if math.isnan(p["error"]) or math.isnan(p["ao_ms"]):
            continue
        dominated = any(
            q is not p and q["ao_ms"] <= p["ao_ms"] and q["error"] <= p["error"]
            and (q["ao_ms"] < p["ao_ms"] or q["error"] < p["error"]) for q in points
            if not math.isnan(q["error"]))
        if not dominated:
            out.append(p)
    return sorted(out, key=lambda p: p["ao_ms"])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csvs", nargs="+", help="METHOD=FILE.csv")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    parser.add_argument("--target-method", default="ssao")
    parser.add_argument("--target", default="ssao.samples=16,ssao.resolution=half",
                        help="the target method's point whose error is the target")
    parser.add_argument("--size", default="800x560")
    parser.add_argument("--errors", action="append", default=[],
                        help="METHOD=FILE.csv: another error of METHOD's sweep, matched by settings (repeatable)")
    parser.add_argument("--plot-error", default="",
                        help="METRIC:BUFFER (e.g. flip:final): the error the plot, front and target table use")
    parser.add_argument("--only", action="append", default=[],
                        help="axis=value: of the rows that have this axis, keep those at this value (repeatable); "
                             "e.g. aov.radius=1, so every method is measured against the same ray-traced AO")
    args = parser.parse_args()

    points = []
    try:
        for item in args.csvs:
            if "=" not in item:
                raise ValueError(f"{item}: give METHOD=FILE.csv")
            label, path = item.split("=", 1)
            points += read(label, path)
        for p in points:
            p["errors"] = {f'{p["metric"]}:{p["buffer"]}': p["error"]}
        kinds = list(dict.fromkeys(f'{p["metric"]}:{p["buffer"]}' for p in points))
        for item in args.errors:
            if "=" not in item:
                raise ValueError(f"--errors {item}: give METHOD=FILE.csv")
            label, path = item.split("=", 1)
            mine = [p for p in points if p["method"] == label]
            if not mine:
                raise ValueError(f"--errors {item}: no main CSV for method '{label}'")
            kind, errors = read_errors(path)
            unmatched = [p["settings"] for p in mine if p["settings"] not in errors]
            if len(unmatched) == len(mine):
                raise ValueError(f"{path}: none of its rows has the settings of {label}'s points "
                                 f"(e.g. {mine[0]['settings']})")
            for p in mine:
                if p["settings"] in errors:
                    p["errors"][kind] = errors[p["settings"]]
            if kind not in kinds:
                kinds.append(kind)
        if args.plot_error and args.plot_error not in kinds:
            raise ValueError(f"--plot-error {args.plot_error}: not among the errors read ({', '.join(kinds)})")
    except (OSError, ValueError, KeyError) as e:
        print(f"ao_methods_plot: {e}", file=sys.stderr)
        return 2
    for item in args.only:
        axis, _, value = item.partition("=")
        points = [p for p in points if axis not in p["values"] or p["values"][axis] == value]
    if not points:
        print("ao_methods_plot: no rows", file=sys.stderr)
        return 2

    if args.errors:
        print(f"Every point's errors (AO passes ms from the METHOD=FILE.csv runs):\n")
        for label in dict.fromkeys(p["method"] for p in points):
            mine = [p for p in points if p["method"] == label]
            names = list(mine[0]["values"].keys())
            print(f"{label}:\n")
            print("| " + " | ".join(names + ["AO passes ms"] + [k.replace(":", " (") + ")" for k in kinds]) + " |")
            print("| " + " | ".join(["---"] * len(names) + ["---:"] * (1 + len(kinds))) + " |")
            for p in mine:
                errs = [f'{p["errors"][k]:.4f}' if k in p["errors"] else "" for k in kinds]
                print("| " + " | ".join([p["values"][n] for n in names] + [f'{p["ao_ms"]:.2f}'] + errs) + " |")
            print()
    if args.plot_error:
        points = [p for p in points if args.plot_error in p["errors"]]
        for p in points:
            p["error"] = p["errors"][args.plot_error]
            p["metric"], p["buffer"] = args.plot_error.split(":", 1)
        if not points:
            print("ao_methods_plot: no rows", file=sys.stderr)
            return 2

    wanted = dict(kv.split("=", 1) for kv in args.target.split(",") if kv)
    target = [p for p in points if p["method"] == args.target_method
              and all(p["values"].get(k) == v for k, v in wanted.items())]
    target_error = target[0]["error"] if target else math.nan
    metric = f'{points[0]["metric"]} of {points[0]["buffer"]}'

    joint = front(points)
    print(f"Joint Pareto front of the AO passes' GPU ms (ao + ao_filter, median) against the {metric}:\n")
    print("| method | settings | AO passes ms | frame ms | error |")
    print("| --- | --- | ---: | ---: | ---: |")
    for p in joint:
        print(f'| {p["method"]} | {p["settings"]} | {p["ao_ms"]:.2f} | {p["frame_ms"]:.1f} | {p["error"]:.4f} |')
    if target:
        print(f"\nAt the error of {args.target_method} {args.target} ({target_error:.4f}) or below, "
              "the cheapest point of each method:\n")
        print("| method | settings | AO passes ms | frame ms | error | AO ms / target's |")
        print("| --- | --- | ---: | ---: | ---: | ---: |")
        for label in dict.fromkeys(p["method"] for p in points):
            ok = [p for p in points if p["method"] == label and p["error"] <= target_error]
            if not ok:
                best = min((p for p in points if p["method"] == label), key=lambda p: p["error"])
                print(f'| {label} | none reaches it (best: {best["settings"]}, {best["error"]:.4f}) | | | | |')
                continue
            p = min(ok, key=lambda p: p["ao_ms"])
            print(f'| {label} | {p["settings"]} | {p["ao_ms"]:.2f} | {p["frame_ms"]:.1f} | {p["error"]:.4f} | '
                  f'{p["ao_ms"] / target[0]["ao_ms"]:.2f} |')

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("ao_methods_plot: matplotlib is missing (apt-get install python3-matplotlib)", file=sys.stderr)
        return 3
    if place_labels is None:
        print(f"ao_methods_plot: cannot import plot_labels.py, which places the labels; it belongs beside {__file__}",
              file=sys.stderr)
        return 4
    w, h = (int(v) for v in args.size.split("x"))
    fig, ax = plt.subplots(figsize=(w / 100, h / 100), dpi=100)
    colours = ["tab:blue", "tab:green", "tab:orange", "tab:purple", "tab:brown"]
    for k, label in enumerate(dict.fromkeys(p["method"] for p in points)):
        mine = [p for p in points if p["method"] == label]
        ax.scatter([p["ao_ms"] for p in mine], [p["error"] for p in mine], s=22, color=colours[k % len(colours)],
                   label=label, zorder=3)
    ax.plot([p["ao_ms"] for p in joint], [p["error"] for p in joint], "-", color="red", lw=1, zorder=2,
            label="front (all methods)")
    if target:
        ax.axhline(target_error, color="grey", ls="--", lw=0.8, label=f"{args.target_method} default's error")
    ax.set_xscale("log")
    ax.set_xlabel("AO passes GPU ms (ao + ao_filter, median; llvmpipe, loaded machine)")
    ax.set_ylabel(metric)
    ax.set_title(args.title, fontsize=10)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    # The front's labels last, once the limits and the layout are final: each where it covers no point,
    # no other label and not the legend, crossing the front and the target's line as little as it can
    # (scripts/plot_labels.py, shared with tradeoff_plot.py).
    labels = [(p["ao_ms"], p["error"], f'{p["method"]} ' + ",".join(v for v in p["values"].values()), "black")
              for p in joint]
    lines = [[(p["ao_ms"], p["error"]) for p in joint]]
    if target:
        lines.append([(x, target_error) for x in ax.get_xlim()])
    place_labels(ax, fig, labels, [(p["ao_ms"], p["error"]) for p in points], lines, fontsize=7, marker=2.5)
    fig.savefig(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
