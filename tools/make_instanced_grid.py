#!/usr/bin/env python3
"""Writes a glTF scene for measuring instancing (BENCHMARKS.md, "Instancing"): an N x N grid of one
sphere mesh (R rings, 2R segments) placed by N^2 nodes, on a floor under a lamp, with a camera.
Rendered as it is, the mesh is stored once and traced through a two-level BVH; with
--flatten-instances, every sphere is stored in world space under one BVH.
Run from the repository root: python3 tools/make_instanced_grid.py OUT_DIR [N] [R]"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_gltf_showcase as showcase  # noqa: E402  (its Builder, sphere and quad)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "instanced_grid"
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    rings = int(sys.argv[3]) if len(sys.argv) > 3 else 70
    os.makedirs(out, exist_ok=True)
    showcase.OUT = out.rstrip("/") + "/"
    b = showcase.Builder()
    grey = b.material({"name": "grey", "pbrMetallicRoughness": {
        "baseColorFactor": [0.7, 0.7, 0.7, 1], "metallicFactor": 0.0, "roughnessFactor": 1.0}})
    sphere = b.mesh(b.geometry(*showcase.sphere(rings, 2 * rings)), grey)
    spacing = 1.0
    half = (n - 1) * spacing / 2
    for i in range(n):
        for j in range(n):
            b.node({"mesh": sphere, "translation": [i * spacing - half, 0.4, j * spacing - half],
                    "scale": [0.4, 0.4, 0.4]})
    b.node({"mesh": b.mesh(b.geometry(*showcase.quad(half + 1, half + 1, 1)), grey)})
    lamp = b.material({"name": "lamp", "emissiveFactor": [1, 1, 1],
                       "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0.0},
                       "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 10.0}}})
    b.node({"mesh": b.mesh(b.geometry(*showcase.quad(half / 2, half / 2, 1, facing_down=True)), lamp),
            "translation": [0, half + 2, 0]})
    b.doc["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    b.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": math.radians(45), "znear": 0.05}}]
    angle = math.radians(-35)
    b.node({"camera": 0, "translation": [0, half * 1.2 + 1, half * 1.7 + 2],
            "rotation": [math.sin(angle / 2), 0, 0, math.cos(angle / 2)]})
    b.doc["buffers"] = [{"uri": "grid.bin", "byteLength": len(b.bin)}]
    b.doc["scenes"] = [{"nodes": list(range(len(b.doc["nodes"])))}]
    b.doc["scene"] = 0
    with open(showcase.OUT + "grid.bin", "wb") as f:
        f.write(b.bin)
    with open(showcase.OUT + "grid.gltf", "w") as f:
        json.dump(b.doc, f, indent=1)
        f.write("\n")
    triangles = len(showcase.sphere(rings, 2 * rings)[3]) // 3
    print("%s: %d spheres of %d triangles: %d drawn" % (showcase.OUT + "grid.gltf", n * n, triangles,
                                                      n * n * triangles))


if __name__ == "__main__":
    main()
