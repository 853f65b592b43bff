#!/usr/bin/env python3
"""Writes the seed corpora in fuzz/corpus/ (small valid inputs that reach every
part of each reader). Run from the repository root; the files are committed,
this script only documents how they were made."""
import base64, json, struct, zlib, os

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")

def write(target, name, data):
    os.makedirs(os.path.join(root, target), exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(root, target, name), mode) as f:
        f.write(data)

# ---- scene JSON
write("scene_json", "shapes_lights_camera.json", json.dumps({
    "name": "seed", "ambient": [0.05, 0.05, 0.05], "background": 0.1,
    "settings": {"tonemap.key": 0.18, "ssao.enabled": True, "lighting.method": "tiled"},
    "lighting": {"direction": [-0.3, -1, -0.4], "intensity": [0.5, 0.5, 0.5], "shadow": True,
                 "lights": [{"name": "s", "pos": [0, 4, 0], "direction": [0, -1, 0], "cutoff": 30, "exponent": 8,
                             "attenuation": {"constant": 1, "linear": 0.1, "quadratic": 0.02}}]},
    "lights": [{"type": "point", "pos": [1, 2, 3], "intensity": [2, 2, 2], "enabled": False},
               {"type": "directional", "direction": [0, -1, 0.2]}],
    "materials": {"red": {"diffuse": [0.8, 0.1, 0.1], "specular": [0.5, 0.5, 0.5], "shininess": 64,
                          "emissive": [0, 0, 0], "opacity": 0.5, "double-sided": True}},
    "objects": [{"shape": "plane", "size": [10, 0, 10], "uv-scale": 2},
                {"shape": "box", "size": [1, 2, 1], "pos": [2, 1, 0], "rotate": [0, 45, 10], "scale": [1, 1, -1], "material": "red"},
                {"shape": "sphere", "radius": 0.5, "material": {"diffuse": [0.2, 0.8, 0.2]}},
                {"shape": "cylinder", "radius": 0.3, "height": 1.5, "pos": [-2, 0, 0]},
                {"shape": "cone", "radius": 0.3, "height": 1}],
    "sky": {"type": "procedural", "zenith": [0.1, 0.2, 0.5], "sun-size": 2, "intensity": 1.5, "rotation": 30},
    "camera": {"pos": [0, 3, 8], "look-at": [0, 0.5, 0], "up": [0, 1, 0], "fov": 50, "near": 0.1, "far": 80,
               "path": [{"time": 0, "pos": [0, 3, 8], "look-at": [0, 0, 0]}, {"time": 2, "pos": [4, 3, 4], "look-at": [0, 0, 0]}]}
}, indent=1))
write("scene_json", "minimal.json", '{"objects": [{"shape": "box"}]}\n')

# ---- presets
write("preset", "camera_and_knobs.json", json.dumps({
    "format": "deferred-workbench preset", "version": 1, "name": "seed", "description": "a seed", "scene": "default",
    "camera": {"pos": [1, 2, 3], "look-at": [0, 0, 0], "up": [0, 1, 0], "fov": 45, "near": 0.1, "far": 100},
    "knobs": {"a.flag": True, "a.count": 8, "a.scale": 2.5, "a.mode": "two"}}, indent=2))
write("preset", "knobs_only.json", '{"knobs": {"a.scale": "0.5", "a.flag": "on"}}\n')

# ---- glTF: a quad with normals, UVs, a 2x2 PNG texture, a camera and lights
def png(w, h, rgba):
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    raw = b"".join(b"\0" + bytes(rgba[y * w * 4:(y + 1) * w * 4]) for y in range(h))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

image = png(2, 2, [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128])
pos = struct.pack("<12f", -1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1)
nrm = struct.pack("<12f", *([0, 1, 0] * 4))
uv = struct.pack("<8f", 0, 0, 1, 0, 1, 1, 0, 1)
idx = struct.pack("<6H", 0, 2, 1, 0, 3, 2) + b"\0\0"
geometry = pos + nrm + uv + idx

def doc(buffer_uri, with_image_view):
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
             {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12}]
    images = [{"uri": "data:image/png;base64," + base64.b64encode(image).decode()}]
    length = len(geometry)
    if with_image_view:
        views.append({"buffer": 0, "byteOffset": len(geometry), "byteLength": len(image)})
        images = [{"bufferView": 4, "mimeType": "image/png"}]
        length += len(image)
    buffer = {"byteLength": length}
    if buffer_uri:
        buffer["uri"] = buffer_uri
    return {
        "asset": {"version": "2.0"}, "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [{"mesh": 0, "rotation": [0, 0.3826834, 0, 0.9238795], "scale": [2, 1, 2]},
                  {"translation": [0, 3, 0], "rotation": [-0.7071068, 0, 0, 0.7071068],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}},
                  {"translation": [2, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 1}},
                   "children": [4]},
                  {"translation": [0, 1, 5], "camera": 0},
                  {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 0, 1], "mesh": 0}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.05, "zfar": 100, "aspectRatio": 1.5}}],
        "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                    "indices": 3, "material": 0}]}],
        "materials": [{"name": "m", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "baseColorTexture": {"index": 0},
                                                             "metallicFactor": 0.2, "roughnessFactor": 0.7},
                       "emissiveFactor": [0.1, 0, 0], "alphaMode": "MASK", "alphaCutoff": 0.4, "doubleSided": True,
                       "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2}}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 33071}],
        "images": images,
        "buffers": [buffer], "bufferViews": views,
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                      {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                      {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "spot", "color": [1, 0.9, 0.8], "intensity": 20, "range": 10,
             "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
            {"type": "point", "intensity": 5}, ]}},
        "extras": {"note": "seed", "nested": [[1, 2], {"a": None}]},
    }

write("gltf", "quad_textured.gltf",
      json.dumps(doc("data:application/octet-stream;base64," + base64.b64encode(geometry).decode(), False), indent=1))
chunk_json = json.dumps(doc(None, True)).encode()
chunk_json += b" " * (-len(chunk_json) % 4)
binary = geometry + image
binary += b"\0" * (-len(binary) % 4)
glb = (b"glTF" + struct.pack("<II", 2, 12 + 8 + len(chunk_json) + 8 + len(binary)) +
       struct.pack("<I", len(chunk_json)) + b"JSON" + chunk_json + struct.pack("<I", len(binary)) + b"BIN\0" + binary)
write("gltf", "quad_textured.glb", glb)
