#!/usr/bin/env python3
"""Writes the race's glTF scene into --out: a textured glTF model under an HDR sky with a sun.

- model.gltf (+ model.bin, PNG textures): a lathed vase (16,384 triangles, smooth normals) with a painted
  base colour texture (metallic 0, roughness 0.45), a copper sphere with a striped base colour texture
  (metallic 1, roughness 0.3) and a checker-textured floor (metallic 0, roughness 0.7). Only what
  tools/race/cycles_render.py can rebuild for Cycles: base colour textures and constant metallic 0 or 1
  and roughness; no normal, roughness or alpha maps, no punctual lights, no emission.
- sky.exr: tools/race/scene_io.py's sky (1024 x 512) with a sun of 2 x 2 texels 40 degrees high.
- scene.json: the camera and the sky.
Used by tools/race_cycles.py --scene gltf."""
import json
import math
import os
import sys

TOOLS = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(TOOLS, "race"))
sys.path.insert(0, TOOLS)
import make_gltf_showcase as gltf  # noqa: E402  (its Builder, png, sphere and quad)
from scene_io import output_folder, sun_direction, write_scene, write_sky  # noqa: E402

LINEAR, REPEAT = 9729, 10497  # glTF sampler enums: no mipmaps, so that Cycles (which has none) filters alike


def srgb_rows(size, colour):
    """size x size RGB texels, colour(u, v) in [0, 1] (sRGB-encoded) for texel centres."""
    return size, [[int(255 * c + 0.5) for x in range(size) for c in colour((x + 0.5) / size, (y + 0.5) / size)]
                  for y in range(size)]


def vase_colour(u, v):
    band = math.sin(v * 30)
    zigzag = abs(((u * 12 + 3 * abs(((v * 8) % 2) - 1)) % 2) - 1)
    if band > 0.6:
        return (0.85, 0.75, 0.45)
    if zigzag < 0.25 and 0.3 < v < 0.7:
        return (0.15, 0.25, 0.55)
    return (0.7, 0.3, 0.2)


def copper_colour(u, v):
    return (0.95, 0.64, 0.54) if int(u * 16) % 2 else (0.8, 0.8, 0.75)


def checker_colour(u, v):
    return (0.75, 0.75, 0.72) if (int(u * 8) + int(v * 8)) % 2 else (0.25, 0.3, 0.35)


def vase(stacks=64, slices=128):
    """A surface of revolution about +y: radius r(y) for y in [0, 1.6], smooth normals from the
    profile's slope, u around, v up."""
    height = 1.6
    radius = lambda y: 0.28 + 0.22 * math.sin(y * 2.6 + 0.3) + 0.05 * math.sin(y * 9)
    slope = lambda y: 0.22 * 2.6 * math.cos(y * 2.6 + 0.3) + 0.05 * 9 * math.cos(y * 9)
    positions, normals, uvs, indices = [], [], [], []
    for i in range(stacks + 1):
        y = height * i / stacks
        r, dr = radius(y), slope(y)
        length = math.sqrt(1 + dr * dr)
        for j in range(slices + 1):
            phi = 2 * math.pi * j / slices
            c, s = math.cos(phi), -math.sin(phi)
            positions += [r * c, y, r * s]
            normals += [c / length, -dr / length, s / length]
            uvs += [j / slices, 1 - i / stacks]
    for i in range(stacks):
        for j in range(slices):
            a, b = i * (slices + 1) + j, (i + 1) * (slices + 1) + j
            indices += [a, a + 1, b, a + 1, b + 1, b]  # counter-clockwise from outside
    return positions, normals, uvs, indices


def main():
    args = output_folder(__doc__)
    gltf.OUT = os.path.join(args.out, "")  # where the Builder writes its textures
    b = gltf.Builder()
    b.doc["asset"]["generator"] = "fragpath tools/make_race_gltf.py"
    b.doc["samplers"] = [{"magFilter": LINEAR, "minFilter": LINEAR, "wrapS": REPEAT, "wrapT": REPEAT}]
    painted = b.texture("vase.png", srgb_rows(256, vase_colour), 3)
    stripes = b.texture("copper.png", srgb_rows(64, copper_colour), 3)
    checker = b.texture("checker.png", srgb_rows(64, checker_colour), 3)
    vase_material = b.material({"name": "vase", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": painted}, "metallicFactor": 0.0, "roughnessFactor": 0.45}})
    copper = b.material({"name": "copper", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": stripes}, "metallicFactor": 1.0, "roughnessFactor": 0.3}})
    floor = b.material({"name": "floor", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": checker}, "metallicFactor": 0.0, "roughnessFactor": 0.7}})
    b.node({"name": "vase", "mesh": b.mesh(b.geometry(*vase()), vase_material), "translation": [-0.45, 0, 0]})
    b.node({"name": "sphere", "mesh": b.mesh(b.geometry(*gltf.sphere(48, 96)), copper),
            "translation": [0.75, 0.45, 0.35], "scale": [0.45, 0.45, 0.45]})
    b.node({"name": "floor", "mesh": b.mesh(b.geometry(*gltf.quad(5, 5, 6)), floor)})
    b.doc["buffers"] = [{"uri": "model.bin", "byteLength": len(b.bin)}]
    b.doc["scenes"] = [{"nodes": list(range(len(b.doc["nodes"])))}]
    b.doc["scene"] = 0
    with open(os.path.join(args.out, "model.bin"), "wb") as f:
        f.write(b.bin)
    with open(os.path.join(args.out, "model.gltf"), "w") as f:
        json.dump(b.doc, f, indent=1)
    write_sky(os.path.join(args.out, "sky.exr"), 1024, 512, sun_direction(40, 50), (160000, 150000, 130000))
    write_scene(args.out, {"mesh": "model.gltf",
                           "camera": {"eye": [0, 1.5, 4.2], "target": [0, 0.6, 0], "up": [0, 1, 0], "fov": 40},
                           "environment": {"map": "sky.exr", "intensity": 1}})


if __name__ == "__main__":
    main()
