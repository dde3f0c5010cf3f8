#!/usr/bin/env python3
"""Writes the race's window room into --out: a closed room (4 wide, 2.7 high, 6 deep; Lambertian walls,
floor, ceiling and two blocks) whose far wall (z = 3) has a window opening 2 x 1.4, lit only by an HDR
sky (sky.exr, 1024 x 512: a blue sky, a brown ground and a sun of 2 x 2 texels, about 0.7 degrees, 30
degrees high, shining in through the window onto the floor). Interior light is indirect but for the sun
patch and the sky seen through the window: the hard case of architectural rendering. scene.json gives
the camera. Used by tools/race_cycles.py --scene window."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "race"))
from scene_io import output_folder, Obj, box_quads, sun_direction, write_scene, write_sky  # noqa: E402

W, H, D = 2.0, 2.7, 3.0  # half width, height, half depth
WINDOW = (-1.0, 1.0, 0.8, 2.2)  # x0, x1, y0, y1 of the opening in the wall z = +D


def main():
    args = output_folder(__doc__)
    obj = Obj()
    # The room's inside faces (counter-clockwise seen from inside; every surface is two-sided anyway).
    obj.quad("floor", [(-W, 0, -D), (W, 0, -D), (W, 0, D), (-W, 0, D)])
    obj.quad("ceiling", [(-W, H, -D), (-W, H, D), (W, H, D), (W, H, -D)])
    obj.quad("wall", [(-W, 0, -D), (-W, H, -D), (W, H, -D), (W, 0, -D)])  # behind the camera
    obj.quad("wall", [(-W, 0, -D), (-W, 0, D), (-W, H, D), (-W, H, -D)])
    obj.quad("wall", [(W, 0, -D), (W, H, -D), (W, H, D), (W, 0, D)])
    x0, x1, y0, y1 = WINDOW
    for (a, b, c, d) in (((-W, 0), (W, 0), (W, y0), (-W, y0)),  # below the window
                         ((-W, y1), (W, y1), (W, H), (-W, H)),  # above it
                         ((-W, y0), (x0, y0), (x0, y1), (-W, y1)),  # left of it
                         ((x1, y0), (W, y0), (W, y1), (x1, y1))):  # right of it
        obj.quad("wall", [(p[0], p[1], D) for p in (a, d, c, b)])
    for quad in box_quads((-1.7, 0, -0.6), (-0.9, 0.9, 0.6)) + box_quads((0.6, 0, 0.8), (1.4, 0.5, 1.6)):
        obj.quad("block", quad)
    obj.write(args.out, "window_room", {"floor": {"Kd": (0.45, 0.32, 0.22)}, "wall": {"Kd": (0.75, 0.75, 0.75)},
                                        "ceiling": {"Kd": (0.8, 0.8, 0.8)}, "block": {"Kd": (0.3, 0.45, 0.6)}})
    # The sun from behind the window, 30 degrees high, 20 degrees to the side: irradiance about 20 on a
    # surface facing it, 10 times the sky's on the ground.
    write_sky(os.path.join(args.out, "sky.exr"), 1024, 512, sun_direction(30, -20), (160000, 150000, 130000))
    write_scene(args.out, {"mesh": "window_room.obj",
                           "camera": {"eye": [0.3, 1.5, -2.8], "target": [-0.2, 0.9, 2.0], "up": [0, 1, 0],
                                      "fov": 60},
                           "environment": {"map": "sky.exr", "intensity": 1}})


if __name__ == "__main__":
    main()
