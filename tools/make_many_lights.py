#!/usr/bin/env python3
# Writes assets/many_lights/: a hall lit by many small lamps, the scene on which the light tree
# (`--light-selection tree`, src/pack/light_tree.h) is measured against the choice by power
# (BENCHMARKS.md, "Samplers"). A 16 x 4 x 24 room (floor, ceiling, four walls, white-grey Lambertian),
# eight pillars, an 8 x 12 grid of 0.3 x 0.3 ceiling lamps facing down in warm and cool colours whose
# power varies 1:20, and 16 wall lamps facing up at the ceiling: 112 emitters, 224 emitter triangles.
# Each point of the floor is lit mostly by the few lamps near it; a choice by power spends most of its
# samples on far ones. Deterministic (fixed seed): rerunning it rewrites the same files.
#
#   tools/make_many_lights.py [--out assets/many_lights] [--grid 8,12] [--wall-lamps 8]
# (--grid 2,2 --wall-lamps 0: four ceiling lamps, 8 emitter triangles, for the threshold of `auto`.)
import argparse
import os
import random

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def main():
    parser = argparse.ArgumentParser(description="write the many-lights hall")
    parser.add_argument("--out", default=os.path.join(ROOT, "assets/many_lights"))
    parser.add_argument("--grid", default="8,12", help="ceiling lamps across and along the hall")
    parser.add_argument("--wall-lamps", type=int, default=8, help="lamps on each side wall")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rng = random.Random(7)
    vertices, faces = [], []  # faces: (material, [v indices])

    def quad(a, b, c, d, material):  # front face: a b c d counter-clockwise seen from it
        first = len(vertices) + 1
        vertices.extend([a, b, c, d])
        faces.append((material, [first, first + 1, first + 2, first + 3]))

    def box(lo, hi, material):  # faces outward
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        quad((x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0), material)  # -z
        quad((x1, y0, z1), (x1, y1, z1), (x0, y1, z1), (x0, y0, z1), material)  # +z
        quad((x0, y0, z1), (x0, y1, z1), (x0, y1, z0), (x0, y0, z0), material)  # -x
        quad((x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1), material)  # +x
        quad((x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0), material)  # +y

    w, h, d = 8.0, 4.0, 12.0  # half-width, height, half-depth
    quad((-w, 0, -d), (-w, 0, d), (w, 0, d), (w, 0, -d), "floor")
    quad((-w, h, -d), (w, h, -d), (w, h, d), (-w, h, d), "walls")  # ceiling, facing down
    quad((-w, 0, d), (-w, h, d), (w, h, d), (w, 0, d), "walls")  # far wall, facing -z
    quad((w, 0, -d), (w, h, -d), (-w, h, -d), (-w, 0, -d), "walls")  # near wall, facing +z
    quad((-w, 0, -d), (-w, h, -d), (-w, h, d), (-w, 0, d), "walls")  # left, facing +x
    quad((w, 0, d), (w, h, d), (w, h, -d), (w, 0, -d), "walls")  # right, facing -x
    for x in (-4.0, 4.0):
        for z in (-7.5, -2.5, 2.5, 7.5):
            box((x - 0.35, 0.0, z - 0.35), (x + 0.35, h, z + 0.35), "pillars")

    lamps = []
    s = 0.15
    across, along = (int(n) for n in args.grid.split(","))
    for i in range(across):
        for j in range(along):
            x, z, y = -w + (i + 0.5) * 2.0 * w / across, -d + (j + 0.5) * 2.0 * d / along, h - 0.4
            name = "lamp%d" % len(lamps)
            warm = rng.random() < 0.5
            power = 1.0 + 19.0 * rng.random() ** 2
            colour = (1.0, 0.75, 0.45) if warm else (0.55, 0.7, 1.0)
            lamps.append((name, tuple(power * c for c in colour)))
            quad((x - s, y, z - s), (x + s, y, z - s), (x + s, y, z + s), (x - s, y, z + s), name)  # down
    for side in (-1.0, 1.0):
        for k in range(args.wall_lamps):
            x, z, y = side * (w - 0.3), -d + (k + 0.5) * 2.0 * d / args.wall_lamps, 2.5
            name = "lamp%d" % len(lamps)
            lamps.append((name, (8.0, 8.0, 7.0)))
            quad((x - s, y, z - s), (x - s, y, z + s), (x + s, y, z + s), (x + s, y, z - s), name)  # up

    with open(os.path.join(args.out, "many_lights.mtl"), "w") as f:
        f.write("# written by tools/make_many_lights.py\n")
        for name, kd in (("floor", (0.55, 0.5, 0.45)), ("walls", (0.7, 0.7, 0.7)), ("pillars", (0.6, 0.3, 0.25))):
            f.write("newmtl %s\nKd %.3f %.3f %.3f\n\n" % ((name,) + kd))
        for name, ke in lamps:
            f.write("newmtl %s\nKd 0 0 0\nKe %.4f %.4f %.4f\n\n" % ((name,) + ke))
    with open(os.path.join(args.out, "many_lights.obj"), "w") as f:
        f.write("# written by tools/make_many_lights.py\nmtllib many_lights.mtl\n")
        for v in vertices:
            f.write("v %g %g %g\n" % v)
        current = None
        for material, idx in faces:
            if material != current:
                f.write("usemtl %s\n" % material)
                current = material
            f.write("f %s\n" % " ".join(str(i) for i in idx))
    with open(os.path.join(args.out, "many_lights.json"), "w") as f:
        f.write('{\n  "mesh": "many_lights.obj",\n'
                '  "camera": {"eye": [0, 2.2, -11.5], "target": [0, 1.2, 0], "up": [0, 1, 0], "fov": 60},\n'
                '  "render": {"width": 256, "height": 256, "spp": 64, "max_depth": 5}\n}\n')
    print("wrote %s: %d lamps, %d quads" % (args.out, len(lamps), len(faces)))


if __name__ == "__main__":
    main()
