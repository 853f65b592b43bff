#!/usr/bin/python3
"""GTAO against the ray-traced AO where the two disagree most: beside a thin
occluder and in the contacts the AO tests hold. Prints one Markdown table row
per setting (docs/ao.md, "Thin occluders: choosing gtao.thin_occluders").

Cases (tests/data/ao/):
- thin_pole_before_wall.json, 240x180: a 0.06-wide pole 0.3 in front of a
  wall; the region is the wall within 6 px (same row) of the pole.
- crease_and_box.json, 160x90 (tests/gl/AoMethodTest.cpp's creaseAndBox):
  the floor within 0.6 of a wall's foot (crease), and the floor under a
  2 x 0.5 x 2 box 0.3 above it (box), as that test's regions.

Per region: GTAO's mean ao.filtered, the ray-traced mean (reference.ao, the
same radius: 1 world unit), and the mean |GTAO - ray-traced| over its pixels.

    PYTHONPATH=build/python /usr/bin/python3 scripts/gtao_thin_occluder_sweep.py \
        [--rays 256] [--set knob=value ...] [thickness=0 thickness=0.25 falloff=0.615,thickness=0.1 ...]

Each positional is one setting: comma-separated gtao.* assignments (the
"gtao." may be left off); none: the knobs' defaults.

--pole RADIUS,DISTANCE[,WxH] (repeatable) measures the pole region only, on
the pole case with the pole's radius and its distance before the wall
changed (and the size), for each setting: how far the choice carries.
"""
import json
import tempfile
import argparse
import os
import sys

import numpy as np

import deferred_workbench as dw

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "tests", "data", "ao")


def look_at_inverse(eye, target):
    """World-from-view rotation of a right-handed look-at camera (up +Y)."""
    eye, target = np.asarray(eye, float), np.asarray(target, float)
    f = target - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, [0.0, 1.0, 0.0])
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    return np.stack([s, u, -f], axis=1), eye  # columns: view x, y, z in world


def world_positions(session, eye, target):
    p = session.render("gbuffer.view_position")
    rot, origin = look_at_inverse(eye, target)
    world = p[..., :3] @ rot.T + origin
    return world, p[..., 3] != 0.0


def pole_region(world, covered):
    wall = covered & (np.abs(world[..., 2]) < 0.05)
    pole = covered & (world[..., 2] > 0.1)
    near = np.zeros_like(wall)
    for dx in range(-6, 7):
        near |= np.roll(pole, dx, axis=1)
    return {"pole": wall & near}


def crease_regions(world, covered):
    floor = covered & (world[..., 1] <= 0.02) & (np.abs(world[..., 2]) <= 5.0)
    x, z = world[..., 0], world[..., 2]
    return {"crease": floor & (x > 0.05) & (x < 0.6),
            "box": floor & (x > 3.2) & (x < 4.8) & (np.abs(z) < 0.8)}


CASES = [
    ("thin_pole_before_wall.json", (240, 180), ([0, 1.5, 5], [0, 1.5, 0]), pole_region),
    ("crease_and_box.json", (160, 90), ([6, 3, 7], [1.5, 0, 0]), crease_regions),
]


def settings_of(text, extra):
    out = dict(extra)
    for part in filter(None, text.split(",")):
        k, v = part.split("=", 1)
        out[k if "." in k else "gtao." + k] = v
    return out


def measure(setting, rays, extra):
    rows = {}
    for name, size, (eye, target), regions in CASES:
        scene = os.path.join(DATA, name)
        base = dw.Session(scene=scene, size=size, settings=dict(extra))
        world, covered = world_positions(base, eye, target)
        truth = base.render("reference.ao", ao_rays=rays)[..., 0]
        s = dw.Session(scene=scene, size=size, settings=settings_of(setting, extra))
        ao = s.render("ao.filtered")[..., 0]
        for region, mask in regions(world, covered).items():
            if mask.sum() < 20:
                sys.exit(f"{name}: region {region} has {mask.sum()} pixels")
            rows[region] = (ao[mask].mean(), truth[mask].mean(), np.abs(ao[mask] - truth[mask]).mean(), int(mask.sum()))
    return rows


def pole_variant(spec, settings, rays, extra):
    parts = spec.split(",")
    radius, distance = float(parts[0]), float(parts[1])
    size = tuple(int(v) for v in parts[2].split("x")) if len(parts) > 2 else (240, 180)
    with open(os.path.join(DATA, "thin_pole_before_wall.json")) as f:
        scene = json.load(f)
    scene["objects"][1]["radius"] = radius
    scene["objects"][1]["pos"][2] = distance
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(scene, f)
    try:
        base = dw.Session(scene=f.name, size=size, settings=dict(extra))
        world, covered = world_positions(base, [0, 1.5, 5], [0, 1.5, 0])
        mask = pole_region(world, covered)["pole"]
        truth = base.render("reference.ao", ao_rays=rays)[..., 0][mask].mean()
        means = [dw.Session(scene=f.name, size=size, settings=settings_of(t, extra)).render("ao.filtered")[..., 0][mask].mean()
                 for t in settings]
    finally:
        os.unlink(f.name)
    return size, truth, means, int(mask.sum())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("settings", nargs="*", default=[""])
    ap.add_argument("--rays", type=int, default=256)
    ap.add_argument("--set", action="append", default=[], help="knob=value for every setting (both runs)")
    ap.add_argument("--pole", action="append", default=[], metavar="RADIUS,DISTANCE[,WxH]")
    a = ap.parse_args()
    extra = dict(kv.split("=", 1) for kv in a.set)
    if a.pole:
        print("| pole radius, distance before the wall, size | ray-traced | " +
              " | ".join(t or "defaults" for t in a.settings) + " |")
        print("| --- | ---: |" + " ---: |" * len(a.settings))
        for spec in a.pole:
            size, truth, means, n = pole_variant(spec, a.settings, a.rays, extra)
            r, z = spec.split(",")[:2]
            print(f"| {r}, {z}, {size[0]}x{size[1]} ({n} px) | {truth:.3f} | " +
                  " | ".join(f"{m:.3f}" for m in means) + " |", flush=True)
        return
    print("| setting | pole: GTAO / ray-traced / mean abs error | crease | box | worst mean abs error |")
    print("| --- | --- | --- | --- | ---: |")
    for setting in a.settings:
        r = measure(setting, a.rays, extra)
        cells = [f"{r[k][0]:.3f} / {r[k][1]:.3f} / {r[k][2]:.3f}" for k in ("pole", "crease", "box")]
        worst = max(r[k][2] for k in r)
        print(f"| {setting or 'defaults'} | " + " | ".join(cells) + f" | {worst:.3f} |", flush=True)
    print("pixels: " + ", ".join(f"{k} {v[3]}" for k, v in r.items()), file=sys.stderr)


if __name__ == "__main__":
    main()
