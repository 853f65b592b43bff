#!/usr/bin/env python3
"""Writes the small hand-made glTF files of tests/data/gltf (run from anywhere;
the files are committed, this says how they were made).

All three are a 2 x 2 grid of quads in the z = 0 plane, facing +Z (9
vertices, 8 counter-clockwise triangles), whose centre vertex (index 4, at
(1, 1, 0)) has a NORMAL of (0, 0, -1): it faces away from all six triangles
around it, so the importer gives each of those corners the face normal on a
vertex of its own (renderer/scene/NormalGenerator.h). Every other attribute of
vertex 4 is distinct from its neighbours', so a test can see that the added
vertices carry it:

- split_corner_tangents.gltf: POSITION, NORMAL, TANGENT, TEXCOORD_0, COLOR_0.
  Every TANGENT is (0, 1, 0, 1) except vertex 4's, (0, -1, 0, -1): valid
  (unit, perpendicular to the face) and unlike what generation would give
  (dP/du = +X).
- split_corner_no_tangents.gltf: the same without TANGENT (generated).
- tangents_without_normals.gltf: POSITION, TANGENT, TEXCOORD_0 and no NORMAL:
  glTF 2.0 3.7.2.1 says flat normals, and the tangents MUST be ignored.
"""
import base64
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
SPLIT = 4


def grid():
    positions, normals, tangents, uvs, colours = [], [], [], [], []
    for j in range(3):
        for i in range(3):
            v = 3 * j + i
            positions += [float(i), float(j), 0.0]
            normals += [0.0, 0.0, -1.0] if v == SPLIT else [0.0, 0.0, 1.0]
            tangents += [0.0, -1.0, 0.0, -1.0] if v == SPLIT else [0.0, 1.0, 0.0, 1.0]
            uvs += [i / 2.0, 1.0 - j / 2.0]  # glTF: v grows down the image
            colours += [0.25, 0.5, 0.75, 1.0] if v == SPLIT else [1.0, 1.0, 1.0, 1.0]
    indices = []
    for j in range(2):
        for i in range(2):
            a, b, c, d = 3 * j + i, 3 * j + i + 1, 3 * (j + 1) + i + 1, 3 * (j + 1) + i
            indices += [a, b, c, a, c, d]
    return positions, normals, tangents, uvs, colours, indices


def write(name, attributes):
    positions, normals, tangents, uvs, colours, indices = grid()
    data = {"POSITION": ("VEC3", positions), "NORMAL": ("VEC3", normals), "TANGENT": ("VEC4", tangents),
            "TEXCOORD_0": ("VEC2", uvs), "COLOR_0": ("VEC4", colours)}
    blob, views, accessors, attrs = b"", [], [], {}
    for key in attributes:
        kind, values = data[key]
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": 4 * len(values)})
        accessor = {"bufferView": len(views) - 1, "componentType": 5126, "count": 9, "type": kind}
        if key == "POSITION":
            accessor["min"], accessor["max"] = [0, 0, 0], [2, 2, 0]
        accessors.append(accessor)
        attrs[key] = len(accessors) - 1
        blob += struct.pack("<%df" % len(values), *values)
    views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": 2 * len(indices)})
    accessors.append({"bufferView": len(views) - 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"})
    blob += struct.pack("<%dH" % len(indices), *indices)
    blob += b"\0" * (-len(blob) % 4)
    doc = {
        "asset": {"version": "2.0", "generator": "tests/data/gltf/make_split_corners.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": attrs, "indices": len(accessors) - 1}]}],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    with open(os.path.join(HERE, name), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


write("split_corner_tangents.gltf", ["POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "COLOR_0"])
write("split_corner_no_tangents.gltf", ["POSITION", "NORMAL", "TEXCOORD_0", "COLOR_0"])
write("tangents_without_normals.gltf", ["POSITION", "TANGENT", "TEXCOORD_0"])
