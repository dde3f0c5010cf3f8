#!/usr/bin/env python3
"""Writes two large textured glTF binaries for timing start-up (BENCHMARKS.md, "glTF start-up: large
textured models"); they are generated, never committed.

- helmet.glb: a helmet-like model, one material on a ~100k-triangle lumpy sphere, with 2048x2048
  baseColor, metallicRoughness (metallic 1; roughness 1 except a band at 0.08, so that it is a glossy
  caustic caster), normal and emissive maps (a glowing visor band; emissiveFactor 1), as the Khronos
  DamagedHelmet has them.
- lamp.glb: a ~6k-triangle desk lamp of five materials (metal base, arm and head, fabric shade, glowing
  bulb, cable), each with its own 2048x2048 baseColor and metallicRoughness maps and some with normal maps.

Only the standard library: the PNGs are written by hand (png()). Run:
    python3 tools/make_big_gltf.py OUT_DIR [--helmet-triangles N] [--texture-size S]"""
import argparse
import json
import math
import os
import struct
import zlib


def png(width, height, rows, channels):
    """An 8-bit RGB or RGBA PNG (PNG spec: signature, IHDR, one IDAT of filter-0 scanlines, IEND)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    colour_type = 6 if channels == 4 else 2
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 6)) +
            chunk(b"IEND", b""))


def pattern_rows(size, texel, seed):
    """size x size RGB rows: texel(x, y) over a 64x64 tile, varied per tile row by `seed` so that rows
    differ (a real map compresses worse than one tile repeated)."""
    tile = 64
    tiles = []
    for ty in range(tile):
        row = bytearray()
        for tx in range(tile):
            row += bytes(texel(tx, ty))
        tiles.append(bytes(row))
    rows = []
    for y in range(size):
        base = tiles[y % tile]
        shift = ((y // tile) * seed * 3) % (tile * 3)
        line = (base[shift:] + base[:shift]) * (size // tile)
        rows.append(line)
    return rows


class Glb:
    def __init__(self, generator):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": generator}, "buffers": [], "bufferViews": [],
                    "accessors": [], "meshes": [], "materials": [], "nodes": [], "images": [],
                    "textures": [], "samplers": [{}], "scenes": [{"nodes": []}], "scene": 0}

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

    def primitive(self, geometry, material):
        positions, normals, uvs, indices = geometry
        return {"attributes": {"POSITION": self.floats(positions, "VEC3"),
                               "NORMAL": self.floats(normals, "VEC3"),
                               "TEXCOORD_0": self.floats(uvs, "VEC2")},
                "indices": self.indices(indices), "material": material}

    def image(self, size, rows):
        self.doc["images"].append({"bufferView": self.view(png(size, size, rows, 3)), "mimeType": "image/png"})
        self.doc["textures"].append({"source": len(self.doc["images"]) - 1, "sampler": 0})
        return {"index": len(self.doc["textures"]) - 1}

    def material(self, m):
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def mesh_node(self, primitives, translation=(0, 0, 0)):
        self.doc["meshes"].append({"primitives": primitives})
        self.doc["nodes"].append({"mesh": len(self.doc["meshes"]) - 1, "translation": list(translation)})
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def write(self, path):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.doc["buffers"] = [{"byteLength": len(self.bin)}]
        text = json.dumps(self.doc, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        body = (struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(self.bin), 0x004E4942) +
                bytes(self.bin))
        with open(path, "wb") as f:
            f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)


def lumpy_sphere(stacks, slices, radius=1.0, lump=0.03, centre=(0, 0, 0)):
    """A UV sphere with small bumps (so that no two triangles are alike), 2 * stacks * (slices - 1)
    triangles."""
    positions, normals, uvs, indices = [], [], [], []
    for i in range(stacks + 1):
        theta = math.pi * i / stacks
        for j in range(slices + 1):
            phi = 2 * math.pi * j / slices
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            r = radius * (1 + lump * math.sin(7 * theta) * math.sin(5 * phi))
            positions += [centre[k] + r * n[k] for k in range(3)]
            normals += n
            uvs += [j / slices, i / stacks]
    for i in range(stacks):
        for j in range(slices):
            a, b = i * (slices + 1) + j, (i + 1) * (slices + 1) + j
            if i > 0:
                indices += [a, a + 1, b]
            if i < stacks - 1:
                indices += [a + 1, b + 1, b]
    return positions, normals, uvs, indices


def cylinder(radius, height, slices, centre):
    """An open tube along y, 2 * slices triangles."""
    positions, normals, uvs, indices = [], [], [], []
    for i in range(2):
        for j in range(slices + 1):
            phi = 2 * math.pi * j / slices
            n = (math.cos(phi), 0.0, math.sin(phi))
            positions += [centre[0] + radius * n[0], centre[1] + height * i, centre[2] + radius * n[2]]
            normals += n
            uvs += [j / slices, i]
    for j in range(slices):
        a, b = j, slices + 1 + j
        indices += [a, b, a + 1, a + 1, b, b + 1]
    return positions, normals, uvs, indices


def colour_map(rgb):
    return lambda x, y: [min(255, c + ((x ^ y) & 15)) for c in rgb]


def roughness_map(glossy_rows, metallic):
    """G roughness 255 except tile rows below `glossy_rows` (G 20: roughness 0.08); B metallic."""
    return lambda x, y: [0, 20 if y < glossy_rows else 255 - (x & 7), metallic]


def normal_map(x, y):
    return [128 + int(40 * math.sin(x / 64 * 2 * math.pi)), 128 + int(40 * math.sin(y / 64 * 2 * math.pi)), 230]


def helmet(out, triangles, size):
    g = Glb("fragpath tools/make_big_gltf.py")
    stacks = max(4, int(math.sqrt(triangles / 2)))
    slices = max(4, triangles // (2 * stacks))
    emissive = lambda x, y: [255, 200, 120] if 24 <= y < 40 else [0, 0, 0]
    m = g.material({"name": "helmet",
                    "pbrMetallicRoughness": {"baseColorTexture": g.image(size, pattern_rows(size, colour_map([150, 140, 120]), 1)),
                                             "metallicRoughnessTexture": g.image(size, pattern_rows(size, roughness_map(8, 255), 2)),
                                             "metallicFactor": 1.0, "roughnessFactor": 1.0},
                    "normalTexture": g.image(size, pattern_rows(size, normal_map, 3)),
                    "emissiveTexture": g.image(size, pattern_rows(size, emissive, 4)),
                    "emissiveFactor": [1.0, 1.0, 1.0]})
    g.mesh_node([g.primitive(lumpy_sphere(stacks, slices), m)])
    g.write(os.path.join(out, "helmet.glb"))


def lamp(out, size):
    g = Glb("fragpath tools/make_big_gltf.py")

    def textured(name, rgb, glossy_rows, metallic, normal=False, extra=None):
        m = {"name": name,
             "pbrMetallicRoughness": {"baseColorTexture": g.image(size, pattern_rows(size, colour_map(rgb), len(g.doc["images"]) + 1)),
                                      "metallicRoughnessTexture": g.image(size, pattern_rows(size, roughness_map(glossy_rows, metallic), len(g.doc["images"]) + 1)),
                                      "metallicFactor": 1.0 if metallic else 0.0, "roughnessFactor": 1.0}}
        if normal:
            m["normalTexture"] = g.image(size, pattern_rows(size, normal_map, len(g.doc["images"]) + 1))
        m.update(extra or {})
        return g.material(m)

    metal = textured("brushed metal", [180, 180, 185], 16, 255, normal=True)
    shade = textured("fabric shade", [200, 60, 40], 0, 0, normal=True)
    bulb = textured("bulb", [255, 250, 230], 0, 0, extra={"emissiveFactor": [1.0, 0.9, 0.6],
                                                             "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 8.0}}})
    cable = textured("cable", [20, 20, 20], 4, 0)
    chrome = textured("chrome joints", [220, 220, 220], 64, 255)
    g.mesh_node([g.primitive(lumpy_sphere(20, 40, 0.5, 0.01, (0, 0.05, 0)), metal),
                 g.primitive(cylinder(0.05, 1.2, 400, (0, 0.1, 0)), metal),
                 g.primitive(lumpy_sphere(24, 40, 0.35, 0.02, (0.3, 1.4, 0)), shade),
                 g.primitive(lumpy_sphere(16, 32, 0.1, 0.0, (0.3, 1.3, 0)), bulb),
                 g.primitive(cylinder(0.01, 1.0, 600, (-0.4, 0.0, 0)), cable),
                 g.primitive(lumpy_sphere(12, 24, 0.08, 0.0, (0, 1.3, 0)), chrome)])
    g.doc["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    g.write(os.path.join(out, "lamp.glb"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--helmet-triangles", type=int, default=100000)
    parser.add_argument("--texture-size", type=int, default=2048)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    helmet(args.out, args.helmet_triangles, args.texture_size)
    lamp(args.out, args.texture_size)


if __name__ == "__main__":
    main()
