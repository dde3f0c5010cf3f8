#!/usr/bin/env python3
"""Writes the race's mesh room into --out: the Cornell box (assets/cornell: its walls, lamp and
materials) with its two blocks replaced by a lumpy blob, an icosphere subdivided 6 times (81,920
triangles, flat-shaded) whose radius is displaced by a few sines of the position, so that traversal of a
real mesh, not of boxes, is what a sample costs. scene.json gives the box's camera. Used by
tools/race_cycles.py --scene mesh."""
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "race"))
from scene_io import output_folder, Obj, write_scene  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORNELL = os.path.join(ROOT, "assets/cornell")
BLOCKS = ("short_block", "tall_block")


def cornell_room(obj):
    """The box's objects but its blocks, as polygons fanned into triangles."""
    vertices, name, material = [], None, None
    for line in open(os.path.join(CORNELL, "cornell.obj")):
        words = line.split()
        if not words:
            continue
        if words[0] == "o":
            name = words[1]
        elif words[0] == "usemtl":
            material = words[1]
        elif words[0] == "v":
            vertices.append(tuple(float(w) for w in words[1:4]))
        elif words[0] == "f" and name not in BLOCKS:
            corners = [obj.vertex(vertices[int(w.split("/")[0]) - 1]) for w in words[1:]]
            for i in range(1, len(corners) - 1):
                obj.triangle(material, corners[0], corners[i], corners[i + 1])


def icosphere(levels):
    """Unit-sphere vertices and counter-clockwise (seen from outside) triangles: an icosahedron whose
    triangles are split in four `levels` times, new vertices pushed out to the sphere."""
    t = (1 + math.sqrt(5)) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
              (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    points = [tuple(c / math.sqrt(1 + t * t) for c in p) for p in points]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        middle, split = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = [(x + y) / 2 for x, y in zip(points[a], points[b])]
                n = math.sqrt(sum(c * c for c in p))
                points.append(tuple(c / n for c in p))
                middle[key] = len(points) - 1
            return middle[key]

        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    return points, faces


def lumpy(p):
    """The blob's radius along unit direction p: 1 with lumps of a few percent to a quarter."""
    x, y, z = p
    return 1 + 0.18 * math.sin(3 * x + 1) * math.sin(4 * y) * math.sin(3.5 * z + 2) + \
        0.06 * math.sin(9 * x + 2 * z) * math.sin(8 * y + 1) + 0.025 * math.sin(23 * y + 17 * z)


def main():
    args = output_folder(__doc__, lambda p: p.add_argument("--levels", type=int, default=6,
                                                          help="subdivisions: 20 x 4^levels triangles"))
    obj = Obj()
    cornell_room(obj)
    points, faces = icosphere(args.levels)
    centre, radius = (278.0, 200.0, 280.0), 150.0
    first = len(obj.vertices) + 1
    for p in points:
        r = radius * lumpy(p)
        obj.vertex(tuple(c + r * d for c, d in zip(centre, p)))
    for a, b, c in faces:
        obj.triangle("blob", first + a, first + b, first + c)
    obj.write(args.out, "mesh_room", {})
    # The box's materials and one for the blob (a pale grey-blue Lambertian).
    shutil.copyfile(os.path.join(CORNELL, "cornell.mtl"), os.path.join(args.out, "mesh_room.mtl"))
    with open(os.path.join(args.out, "mesh_room.mtl"), "a") as f:
        f.write("\nnewmtl blob\nKd 0.6 0.65 0.7\n")
    write_scene(args.out, {"mesh": "mesh_room.obj",
                           "camera": {"eye": [278, 273, -800], "target": [278, 273, 0], "up": [0, 1, 0],
                                      "fov": 39.3}})


if __name__ == "__main__":
    main()
