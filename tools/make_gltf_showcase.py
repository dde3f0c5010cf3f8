#!/usr/bin/env python3
"""Writes assets/gltf_showcase/: a glTF 2.0 scene that shows what the glTF path reads, for the README's
render and the render tests.

- A grid of spheres, 13 meshes (one per material) sharing one sphere's accessors: metallic 0 (blue)
  and 1 (gold) in two rows, roughness 0.05 to 1 across, and one glass sphere
  (KHR_materials_transmission, KHR_materials_ior).
- A floor with a base colour texture (grey tiles) and a tangent-space normal map (bevelled tile edges)
  repeated 4 times, roughness 0.5 from a metallic-roughness texture.
- A leaf-shaped cut-out (alphaMode MASK over a texture's alpha), single-sided (glTF's default).
- An emissive panel (KHR_materials_emissive_strength), a spot light and a directional light
  (KHR_lights_punctual), and a perspective camera.
- showcase.json: the glTF under a dim blue sky (a scene file's environment).

Run from the repository root: python3 tools/make_gltf_showcase.py"""
import base64
import json
import math
import os
import struct
import zlib

OUT = "assets/gltf_showcase/"


def png(width, height, rows, channels):
    """An 8-bit RGB or RGBA PNG (PNG spec: signature, IHDR, one IDAT of filter-0 scanlines, IEND)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    colour_type = 6 if channels == 4 else 2
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) +
            chunk(b"IEND", b""))


TILE, TILES = 32, 4  # texels per tile, tiles per texture side


def tile_colour_rows():
    size = TILE * TILES
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            light = (x // TILE + y // TILE) % 2 == 0
            row += [200, 190, 175] if light else [120, 115, 110]
        rows.append(row)
    return size, rows


def tile_normal_rows():
    """Each tile's outer 4 texels slope down toward the grout: the normal leans away from the tile's
    centre there (x right, y up in the image, as glTF's tangent space has it)."""
    size, bevel, lean = TILE * TILES, 4, 0.7
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            tx, ty = x % TILE, y % TILE
            nx = -lean if tx < bevel else lean if tx >= TILE - bevel else 0.0
            ny = lean if ty < bevel else -lean if ty >= TILE - bevel else 0.0  # image rows run down
            length = math.sqrt(nx * nx + ny * ny + 1.0)
            row += [round((c / length * 0.5 + 0.5) * 255) for c in (nx, ny, 1.0)]
        rows.append(row)
    return size, rows


def roughness_rows():
    return 1, [[0, 128, 0]]  # G: roughness 0.5, B: metallic 0


def leaf_rows():
    """A leaf: an ellipse with a notch, green, alpha 255 inside and 0 outside."""
    size = 64
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            u, v = (x + 0.5) / size * 2 - 1, (y + 0.5) / size * 2 - 1
            inside = (u / 0.55) ** 2 + v * v < 1.0 and not (abs(u) < 0.04 and v > 0.2)
            row += [60, 150, 50, 255 if inside else 0]
        rows.append(row)
    return size, rows


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "fragpath tools/make_gltf_showcase.py"},
                    "buffers": [], "bufferViews": [], "accessors": [], "meshes": [], "materials": [],
                    "nodes": [], "images": [], "textures": [], "samplers": [{}]}

    def view(self, data, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin += data
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def floats(self, values, kind):
        width = {"VEC2": 2, "VEC3": 3}[kind]
        data = struct.pack("<%df" % len(values), *values)
        accessor = {"bufferView": self.view(data, 34962), "componentType": 5126,
                    "count": len(values) // width, "type": kind}
        if kind == "VEC3":
            columns = [values[i::3] for i in range(3)]
            accessor["min"] = [min(c) for c in columns]
            accessor["max"] = [max(c) for c in columns]
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def indices(self, values):
        data = struct.pack("<%dI" % len(values), *values)
        self.doc["accessors"].append({"bufferView": self.view(data, 34963), "componentType": 5125,
                                      "count": len(values), "type": "SCALAR"})
        return len(self.doc["accessors"]) - 1

    def geometry(self, positions, normals, uvs, indices):
        """Accessors that any number of meshes may share."""
        attributes = {"POSITION": self.floats(positions, "VEC3"), "NORMAL": self.floats(normals, "VEC3"),
                      "TEXCOORD_0": self.floats(uvs, "VEC2")}
        return attributes, self.indices(indices)

    def mesh(self, geometry, material):
        attributes, indices = geometry
        self.doc["meshes"].append({"primitives": [{"attributes": attributes, "indices": indices,
                                                   "material": material}]})
        return len(self.doc["meshes"]) - 1

    def material(self, m):
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def texture(self, name, size_rows, channels):
        size, rows = size_rows
        with open(OUT + name, "wb") as f:
            f.write(png(size, size, rows, channels))
        self.doc["images"].append({"uri": name})
        self.doc["textures"].append({"source": len(self.doc["images"]) - 1, "sampler": 0})
        return len(self.doc["textures"]) - 1

    def node(self, n):
        self.doc["nodes"].append(n)
        return len(self.doc["nodes"]) - 1


def sphere(stacks=24, slices=48):
    positions, normals, uvs, indices = [], [], [], []
    for i in range(stacks + 1):
        theta = math.pi * i / stacks
        for j in range(slices + 1):
            phi = 2 * math.pi * j / slices
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            positions += n
            normals += n
            uvs += [j / slices, i / stacks]
    for i in range(stacks):
        for j in range(slices):
            a, b = i * (slices + 1) + j, (i + 1) * (slices + 1) + j
            if i > 0:
                indices += [a, b, a + 1]
            if i < stacks - 1:
                indices += [a + 1, b, b + 1]
    return positions, normals, uvs, indices


def quad(half_x, half_z, uv_repeat, facing_down=False):
    """A square in y = 0 facing +y (or -y), counter-clockwise from its front."""
    p = [-half_x, 0, half_z, half_x, 0, half_z, half_x, 0, -half_z, -half_x, 0, -half_z]
    n = [0, -1 if facing_down else 1, 0] * 4
    uv = [0, uv_repeat, uv_repeat, uv_repeat, uv_repeat, 0, 0, 0]
    idx = [0, 2, 1, 0, 3, 2] if facing_down else [0, 1, 2, 0, 2, 3]
    return p, n, uv, idx


def main():
    os.makedirs(OUT, exist_ok=True)
    b = Builder()
    tiles = b.texture("tiles.png", tile_colour_rows(), 3)
    bumps = b.texture("tiles_normal.png", tile_normal_rows(), 3)
    rough = b.texture("tiles_roughness.png", roughness_rows(), 3)
    leaf = b.texture("leaf.png", leaf_rows(), 4)

    floor_material = b.material({"name": "tiles", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": tiles}, "metallicRoughnessTexture": {"index": rough},
        "metallicFactor": 1.0, "roughnessFactor": 1.0}, "normalTexture": {"index": bumps, "scale": 1.0}})
    floor = b.mesh(b.geometry(*quad(6, 6, 4)), floor_material)
    b.node({"name": "floor", "mesh": floor})

    sphere_geometry = b.geometry(*sphere())
    roughness = [0.05, 0.2, 0.4, 0.6, 0.8, 1.0]
    rows = [("blue plastic", [0.1, 0.25, 0.7, 1.0], 0.0), ("gold", [1.0, 0.78, 0.34, 1.0], 1.0)]
    for r, (name, colour, metallic) in enumerate(rows):
        for c, rough_value in enumerate(roughness):
            m = b.material({"name": "%s %.2f" % (name, rough_value), "pbrMetallicRoughness": {
                "baseColorFactor": colour, "metallicFactor": metallic, "roughnessFactor": rough_value}})
            mesh = b.mesh(sphere_geometry, m)
            b.node({"name": "%s %d" % (name, c), "mesh": mesh,
                    "translation": [-2.75 + 1.1 * c, 0.45, 0.4 - 1.4 * r], "scale": [0.45, 0.45, 0.45]})
    glass = b.material({"name": "glass", "pbrMetallicRoughness": {"metallicFactor": 0.0, "roughnessFactor": 0.0},
                        "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                       "KHR_materials_ior": {"ior": 1.5}}})
    glass_mesh = b.mesh(sphere_geometry, glass)
    b.node({"name": "glass", "mesh": glass_mesh, "translation": [1.1, 0.6, 1.9], "scale": [0.6, 0.6, 0.6]})

    leaf_material = b.material({"name": "leaf", "alphaMode": "MASK", "alphaCutoff": 0.5, "pbrMetallicRoughness": {
        "baseColorTexture": {"index": leaf}, "metallicFactor": 0.0, "roughnessFactor": 0.7}})
    leaf_mesh = b.mesh(b.geometry(*quad(0.6, 0.6, 1)), leaf_material)
    # Stood upright facing the camera (+z): a quarter turn about x.
    s = math.sqrt(0.5)
    b.node({"name": "leaf", "mesh": leaf_mesh, "translation": [-1.2, 0.6, 1.9], "rotation": [s, 0, 0, s]})

    panel_material = b.material({"name": "panel", "emissiveFactor": [1.0, 0.9, 0.8],
                                 "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0.0},
                                 "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 6.0}}})
    panel = b.mesh(b.geometry(*quad(1.5, 0.75, 1, facing_down=True)), panel_material)
    b.node({"name": "panel", "mesh": panel, "translation": [0, 4.0, 0.5]})

    b.doc["extensionsUsed"] = ["KHR_lights_punctual", "KHR_materials_transmission", "KHR_materials_ior",
                               "KHR_materials_emissive_strength"]
    b.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "spot", "name": "spot", "color": [1.0, 0.85, 0.6], "intensity": 40.0,
         "spot": {"innerConeAngle": 0.25, "outerConeAngle": 0.45}},
        {"type": "directional", "name": "sky fill", "color": [0.6, 0.7, 1.0], "intensity": 0.6}]}}
    # The spot at (-3, 4, 4) aimed at the grid's centre; its node's -z is the light's direction.
    def look_rotation(eye, target):
        f = [t - e for t, e in zip(target, eye)]
        length = math.sqrt(sum(c * c for c in f))
        f = [c / length for c in f]
        # The rotation that takes -z to f: axis (-z) x f, angle acos(-z . f).
        axis = [f[1], -f[0], 0.0]
        sin_angle = math.sqrt(axis[0] ** 2 + axis[1] ** 2)
        angle = math.atan2(sin_angle, -f[2])
        axis = [c / sin_angle for c in axis]
        return [c * math.sin(angle / 2) for c in axis] + [math.cos(angle / 2)]
    b.node({"name": "spot", "translation": [-3, 4, 4], "rotation": look_rotation([-3, 4, 4], [0, 0, -0.5]),
            "extensions": {"KHR_lights_punctual": {"light": 0}}})
    b.node({"name": "sun", "rotation": look_rotation([0, 0, 0], [0.3, -1.0, -0.5]),
            "extensions": {"KHR_lights_punctual": {"light": 1}}})

    b.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": math.radians(38), "znear": 0.05}}]
    b.node({"name": "camera", "camera": 0, "translation": [0, 3.0, 6.8],
            "rotation": look_rotation([0, 3.0, 6.8], [0, 0.3, 0])})

    b.doc["buffers"] = [{"uri": "showcase.bin", "byteLength": len(b.bin)}]
    b.doc["scenes"] = [{"nodes": list(range(len(b.doc["nodes"])))}]
    b.doc["scene"] = 0
    with open(OUT + "showcase.bin", "wb") as f:
        f.write(b.bin)
    with open(OUT + "showcase.gltf", "w") as f:
        json.dump(b.doc, f, indent=1)
        f.write("\n")
    # A scene file for what glTF cannot say: a dim blue sky for the metals to reflect.
    with open(OUT + "showcase.json", "w") as f:
        json.dump({"mesh": "showcase.gltf", "environment": {"color": [0.15, 0.18, 0.25]}}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
