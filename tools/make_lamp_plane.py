#!/usr/bin/env python3
"""Writes the race's analytic scene into --out: a Lambertian plane of albedo 0.5 (40 x 40 at y = 0) under a
one-sided square lamp of radiance 1, side 2, 1 above, emitting down; no environment. Under the lamp's
centre the plane's radiance is 0.5 x the form factor 0.554126 = 0.277063 (tests/render/analytic_lamp.h).
The camera is a pinhole halfway between lamp and plane looking straight down with a 2-degree field, so
its image is a spot of radius 0.009 where the form factor is constant to 1e-5 (as lampCamera there).
Used by tools/race_cycles.py --analytic."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "race"))
from scene_io import output_folder, Obj, write_scene  # noqa: E402


def main():
    args = output_folder(__doc__)
    obj = Obj()
    f = 20.0
    obj.quad("plane", [(-f, 0, -f), (-f, 0, f), (f, 0, f), (f, 0, -f)])  # counter-clockwise from above
    obj.quad("lamp", [(-1, 1, -1), (1, 1, -1), (1, 1, 1), (-1, 1, 1)])  # counter-clockwise from below
    obj.write(args.out, "lamp_plane", {"plane": {"Kd": (0.5, 0.5, 0.5)},
                                       "lamp": {"Kd": (0, 0, 0), "Ke": (1, 1, 1)}})
    write_scene(args.out, {"mesh": "lamp_plane.obj",
                           "camera": {"eye": [0, 0.5, 0], "target": [0, 0, 0], "up": [0, 0, 1], "fov": 2}})


if __name__ == "__main__":
    main()
