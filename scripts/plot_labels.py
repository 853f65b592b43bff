"""Label placement shared by the plot scripts (tradeoff_plot.py,
ao_methods_plot.py): each label goes where its text overlaps no label placed
before it, no point and not the legend, inside the axes. The scripts import
it from their own folder (`tradeoff --plot` runs scripts/tradeoff_plot.py, or
the installed copy in share/deferred-workbench beside this file).

It needs matplotlib only through the axes and figure it is given.
"""

# Offsets around a point, in directions of (x, y) signs: right-above first (the
# usual place), then the other seven directions.
DIRECTIONS = [(1, 1), (1, -1), (-1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1)]


def place_labels(ax, fig, labels, points, lines=(), fontsize=8, marker=3.0, step=6.0, rings=6):
    """Annotates each (x, y, text, color) of `labels` (x, y in data units)
    where its text box overlaps no label placed before it, no point of
    `points` (data x, y; each a square `marker` points from its centre each
    way) and not the legend, stays inside the axes and crosses as little as
    it can of `lines` (each a list of data (x, y) vertices, e.g. the Pareto
    front; a pixel of line inside a label costs as much as a square pixel of
    overlap). A greedy search: offsets around the point in 8 directions
    (right-above first), ring k `k * step` points away, up to `rings` rings;
    the first spot that costs nothing is taken, else the cheapest. A label
    anywhere but right-above in the first ring gets a thin leader line from
    its point to the text's nearest edge.

    Call it last, once the axes' limits, scales and the layout are final (it
    draws the figure to measure the text). Returns the placed labels' boxes
    in display pixels (x0, y0, x1, y1), in the order of `labels`.
    """
    if not labels:
        return []
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    area = ax.get_window_extent(renderer)
    to_px = ax.transData.transform
    pad = marker * fig.dpi / 72.0
    markers = []
    for x, y in points:
        px, py = to_px((x, y))
        markers.append((px - pad, py - pad, px + pad, py + pad))
    # The lines as dots a pixel apart (straight in display space, log axes included).
    dots = []
    for line in lines:
        vertices = [to_px(v) for v in line]
        for (x0, y0), (x1, y1) in zip(vertices, vertices[1:]):
            n = max(1, int(((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5))
            dots += [(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * i / n) for i in range(n + 1)]
    obstacles = []
    legend = ax.get_legend()
    if legend is not None:
        e = legend.get_window_extent(renderer)
        obstacles.append((e.x0, e.y0, e.x1, e.y1))

    def overlap(a, b):
        w = min(a[2], b[2]) - max(a[0], b[0])
        h = min(a[3], b[3]) - max(a[1], b[1])
        return w * h if w > 0 and h > 0 else 0.0

    def outside(box):
        return (max(0.0, area.x0 - box[0]) + max(0.0, box[2] - area.x1)) * (box[3] - box[1]) + \
               (max(0.0, area.y0 - box[1]) + max(0.0, box[3] - area.y1)) * (box[2] - box[0])

    boxes = []
    for x, y, text, color in labels:
        best = None
        for ring in range(1, rings + 1):
            for dx, dy in DIRECTIONS:
                ox, oy = step * ring * dx, step * ring * dy
                ha = "left" if dx > 0 else "right" if dx < 0 else "center"
                va = "bottom" if dy > 0 else "top" if dy < 0 else "center"
                note = ax.annotate(text, (x, y), textcoords="offset points", xytext=(ox, oy), fontsize=fontsize,
                                   color=color, ha=ha, va=va, zorder=5)
                e = note.get_window_extent(renderer)
                box = (e.x0, e.y0, e.x1, e.y1)
                cost = sum(overlap(box, b) for b in obstacles) + sum(overlap(box, m) for m in markers) + outside(box)
                cost += sum(1 for u, v in dots if box[0] <= u <= box[2] and box[1] <= v <= box[3])
                if best is None or cost < best[0]:
                    if best is not None:
                        best[1].remove()
                    best = (cost, note, box, (ring, dx, dy))
                else:
                    note.remove()
                if cost == 0:
                    break
            if best[0] == 0:
                break
        _, note, box, where = best
        if where != (1, 1, 1):
            # To the box's nearest point, so the line stops at the text.
            px, py = to_px((x, y))
            end = (min(max(px, box[0]), box[2]), min(max(py, box[1]), box[3]))
            ax.annotate("", (x, y), xytext=end, textcoords="figure pixels",
                        arrowprops=dict(arrowstyle="-", color=color, alpha=0.5, lw=0.6, shrinkA=0, shrinkB=2),
                        zorder=4)
        obstacles.append(box)
        boxes.append(box)
    return boxes
