#!/usr/bin/env python3
"""Writes two large textured glTF binaries for timing start-up (BENCHMARKS.md, "glTF start-up: large
textured models"); they are generated, never committed.

- helmet.glb: a helmet-like model, one material on a ~100k-triangle lumpy sphere, with 2048x2048
  baseColor, metallicRoughness (metallic 1; roughness 1 except a band at 0.08, so that it is a glossy
  caustic caster), normal and emissive maps (a glowing visor band; emissiveFactor 1), as the Khronos
  DamagedHelmet has them.
- lamp.glb: a ~6k-triangle desk lamp of five materials (metal base, arm and head, fabric shade, glowing
  bulb, cable), each with its own 2048x2048 baseColor and metallicRoughness maps and some with normal maps.
- parts.glb: 1500 small parts (168k triangles), each under its own node, 375 materials sharing four
  256x256 maps, every tenth mesh drawn twice (instances).

Only the standard library: the PNGs and the glTF structure come from make_gltf_showcase.py. Run:
    python3 tools/make_big_gltf.py OUT_DIR [--helmet-triangles N] [--texture-size S] [--parts N]"""
import argparse
import json
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_gltf_showcase import Builder, png, sphere  # noqa: E402


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


class Glb(Builder):
    """make_gltf_showcase's builder, writing one .glb with the images inside it."""

    def __init__(self, generator):
        super().__init__()
        self.doc["asset"]["generator"] = generator
        self.doc["scenes"] = [{"nodes": []}]
        self.doc["scene"] = 0

    def primitive(self, geometry, material):
        positions, normals, uvs, indices = geometry
        attributes, index_accessor = self.geometry(positions, normals, uvs, indices)
        return {"attributes": attributes, "indices": index_accessor, "material": material}

    def image(self, size, rows):
        self.doc["images"].append({"bufferView": self.view(png(size, size, rows, 3)), "mimeType": "image/png"})
        self.doc["textures"].append({"source": len(self.doc["images"]) - 1, "sampler": 0})
        return {"index": len(self.doc["textures"]) - 1}

    def mesh_node(self, primitives, translation=(0, 0, 0)):
        self.doc["meshes"].append({"primitives": primitives})
        self.doc["scenes"][0]["nodes"].append(self.node({"mesh": len(self.doc["meshes"]) - 1,
                                                         "translation": list(translation)}))

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
    """make_gltf_showcase's UV sphere with small bumps (so that no two triangles are alike), scaled and
    moved: 2 * stacks * (slices - 1) triangles."""
    unit, normals, uvs, indices = sphere(stacks, slices)
    positions = []
    for v in range(len(unit) // 3):
        theta, phi = math.pi * (v // (slices + 1)) / stacks, 2 * math.pi * (v % (slices + 1)) / slices
        r = radius * (1 + lump * math.sin(7 * theta) * math.sin(5 * phi))
        positions += [centre[k] + r * unit[3 * v + k] for k in range(3)]
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


def parts(out, count, size):
    """`count` small parts (a machine's or a city's many nodes): each a sphere of 112 triangles under
    its own node, with one of count / 4 materials, which share 4 small maps; every tenth mesh is drawn
    by two nodes (an instance). Finds costs that grow with nodes x meshes or materials x triangles."""
    g = Glb("fragpath tools/make_big_gltf.py")
    maps = [g.image(size, pattern_rows(size, roughness_map(8 * k, 255 if k % 2 else 0), k + 1)) for k in range(4)]
    materials = [g.material({"name": "part %d" % k,
                             "pbrMetallicRoughness": {"baseColorFactor": [0.2 + 0.6 * (k % 5) / 4, 0.5, 0.5, 1.0],
                                                      "metallicRoughnessTexture": maps[k % 4],
                                                      "metallicFactor": float(k % 2), "roughnessFactor": 1.0}})
                 for k in range(max(1, count // 4))]
    side = int(math.ceil(math.sqrt(count)))
    geometry = lumpy_sphere(8, 8, 0.4, 0.05)
    for k in range(count):
        translation = (k % side - side / 2, 0, k // side - side / 2)
        g.mesh_node([g.primitive(geometry, materials[k % len(materials)])], translation)
        if k % 10 == 0:
            g.doc["scenes"][0]["nodes"].append(g.node({"mesh": len(g.doc["meshes"]) - 1,
                                                       "translation": [translation[0], 1.0, translation[2]]}))
    g.write(os.path.join(out, "parts.glb"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--helmet-triangles", type=int, default=100000)
    parser.add_argument("--texture-size", type=int, default=2048)
    parser.add_argument("--parts", type=int, default=1500)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    helmet(args.out, args.helmet_triangles, args.texture_size)
    lamp(args.out, args.texture_size)
    parts(args.out, args.parts, 256)


if __name__ == "__main__":
    main()
