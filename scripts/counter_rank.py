#!/usr/bin/env python3
"""How well each cost counter ranks a bench run's configurations against their measured GPU time.

Reads a bench samples CSV that carries the counter columns (bench's default;
docs/bench.md, "Cost counters") and prints, for the frame and for each --pass,
the Spearman rank correlation over the configurations between each counter
(the first counted frame's; they repeat) and the median GPU ms of that span.
Ties get their mean rank; a counter that is the same everywhere has no
correlation (printed as "-").

    scripts/counter_rank.py --csv bench.csv --pass ao --pass lighting
"""
import argparse
import csv
import statistics
import sys

COUNTERS = ["fragments", "samples", "primitives", "vertices", "compute", "bytes"]


def ranks(values):
    """1-based ranks, ties sharing their mean rank."""
    order = sorted(range(len(values)), key=lambda i: values[i])
    out = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            out[order[k]] = (i + j) / 2.0 + 1.0
        i = j + 1
    return out


def spearman(x, y):
    """Pearson's correlation of the ranks; None when either side is constant."""
    rx, ry = ranks(x), ranks(y)
    mx, my = statistics.fmean(rx), statistics.fmean(ry)
    sxy = sum((a - mx) * (b - my) for a, b in zip(rx, ry))
    sxx = sum((a - mx) ** 2 for a in rx)
    syy = sum((b - my) ** 2 for b in ry)
    return None if sxx == 0 or syy == 0 else sxy / (sxx * syy) ** 0.5


def read(path):
    """{span: {config: ([gpu ms], {counter: first value})}}."""
    spans = {}
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if not header or header[-len(COUNTERS):] != COUNTERS:
            raise ValueError(f"{path}: not a bench samples CSV with counter columns (bench without --no-counters)")
        index = {name: i for i, name in enumerate(header)}
        for row in reader:
            if not row:
                continue
            span, config = row[index["pass"]], int(row[index["config"]])
            ms, counts = spans.setdefault(span, {}).setdefault(config, ([], {}))
            ms.append(float(row[index["gpu_ms"]]))
            for c in COUNTERS:
                if row[index[c]] != "" and c not in counts:
                    counts[c] = int(row[index[c]])
    return spans


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True)
    parser.add_argument("--pass", dest="passes", action="append", default=[], help="a pass to rank too (repeatable)")
    args = parser.parse_args()
    try:
        spans = read(args.csv)
    except (ValueError, OSError) as e:
        print(f"counter_rank: {e}", file=sys.stderr)
        return 2
    print("span        configs  " + "  ".join(f"{c:>10}" for c in COUNTERS))
    for span in ["frame"] + args.passes:
        if span not in spans:
            print(f"counter_rank: no rows of '{span}' in {args.csv}", file=sys.stderr)
            return 2
        configs = sorted(c for c, (_, counts) in spans[span].items() if counts)
        ms = [statistics.median(spans[span][c][0]) for c in configs]
        cells = []
        for counter in COUNTERS:
            values = [spans[span][c][1].get(counter) for c in configs]
            rho = None if None in values else spearman(values, ms)
            cells.append(f"{rho:>10.3f}" if rho is not None else f"{'-':>10}")
        print(f"{span:<11} {len(configs):>7}  " + "  ".join(cells))
    return 0


if __name__ == "__main__":
    sys.exit(main())
