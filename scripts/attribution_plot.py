#!/usr/bin/env python3
"""Plots a `deferred-workbench tradeoff --attribute` CSV: for each
approximation family, the error it removes when made exact alone
(as_is - only_exact) and the error it adds when left approximate alone
(only_approximate - all_exact), as bars with their 95% paired intervals, and
the total (as_is - all_exact) as a line. A part whose interval holds 0 is
drawn hatched: it cannot be told from none. `tradeoff --attribute --plot
FILE.png` runs it; by hand:

    python3 scripts/attribution_plot.py --csv attribution.csv --out attribution.png [--size 800x500]

Exit codes: 0 drawn, 1 the plot could not be written, 2 bad arguments or
CSV, 3 matplotlib is missing (Debian: apt-get install python3-matplotlib).
"""
import argparse
import csv
import math
import sys

COLUMNS = ["row", "metric", "buffer", "error", "error_lo", "error_hi", "only_exact", "only_exact_lo",
           "only_exact_hi", "only_approximate", "only_approximate_lo", "only_approximate_hi", "removed",
           "removed_lo", "removed_hi", "added", "added_lo", "added_hi", "sets"]


def number(text):
    return math.nan if text == "" else float(text)


def short_interval(value, lo, hi):
    """'0.0691 [0.0615, 0.0778]'; the value alone without an interval."""
    if lo == "" or hi == "":
        return "%.3g" % value
    return "%.3g [%.3g, %.3g]" % (value, float(lo), float(hi))


def read(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if header != COLUMNS:
            raise ValueError(f"{path}: not a tradeoff --attribute CSV (header {header})")
        rows = [dict(zip(header, line)) for line in reader]
    if len(rows) < 2 or rows[0]["row"] != "as_is" or rows[1]["row"] != "all_exact":
        raise ValueError(f"{path}: expected the rows as_is and all_exact first")
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", default="800x500")
    args = parser.parse_args()
    try:
        width, height = (int(v) for v in args.size.split("x"))
        rows = read(args.csv)
    except (ValueError, OSError) as e:
        print(f"attribution_plot: {e}", file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("attribution_plot: matplotlib is missing (Debian: apt-get install python3-matplotlib)", file=sys.stderr)
        return 3
    families = rows[2:]
    dpi = 100
    fig, ax = plt.subplots(figsize=(width / dpi, height / dpi), dpi=dpi)
    bar = 0.38
    for k, (part, label) in enumerate([("removed", "removed: as_is - only_exact"),
                                       ("added", "added: only_approximate - all_exact")]):
        for i, r in enumerate(families):
            v, lo, hi = number(r[part]), number(r[part + "_lo"]), number(r[part + "_hi"])
            if math.isnan(v):
                continue
            unclear = not (lo > 0 or hi < 0)
            ax.bar(i + (k - 0.5) * bar, v, bar, color=f"C{k}", alpha=0.45 if unclear else 0.9,
                   hatch="//" if unclear else None)
            ax.errorbar(i + (k - 0.5) * bar, v, yerr=[[max(0.0, v - lo)], [max(0.0, hi - v)]], color="black",
                        capsize=3, linewidth=1)
    # The legend from its own handles: a bar's style (hatched when its interval holds 0) is not the series'.
    from matplotlib.patches import Patch
    from matplotlib.lines import Line2D
    handles = [Patch(color="C0", alpha=0.9, label="removed: as_is - only_exact"),
               Patch(color="C1", alpha=0.9, label="added: only_approximate - all_exact"),
               Patch(facecolor="white", edgecolor="grey", hatch="//", label="interval holds 0")]
    total = number(rows[1]["removed"])
    if not math.isnan(total):
        ax.axhline(total, color="C3", linestyle="--", linewidth=1)
        handles.append(Line2D([], [], color="C3", linestyle="--", label="total as_is - all_exact %s"
                              % short_interval(total, rows[1]["removed_lo"], rows[1]["removed_hi"])))
    ax.axhline(0.0, color="black", linewidth=0.6)
    ax.set_xticks(range(len(families)))
    ax.set_xticklabels([r["row"] for r in families], rotation=30, ha="right")
    metric, buffer = rows[0]["metric"], rows[0]["buffer"]
    ax.set_ylabel(f"{metric} of {buffer}: the family's part (95% CI, paired)")
    ax.set_title("where the error comes from: as is %.3g, all exact %.3g"
                 % (number(rows[0]["error"]), number(rows[1]["error"])), fontsize=9)
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=2, fontsize=8)
    fig.tight_layout()
    try:
        fig.savefig(args.out, format="png")
    except OSError as e:
        print(f"attribution_plot: {args.out}: cannot write the plot: {e.strerror or e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
