#!/usr/bin/env python3
"""Writes the race's second analytic scene into --out: a grey Lambertian plane (albedo 0.5, 100 x 100 at
y = 0) under tools/race/scene_io.py's sky with a small bright sun (1024 x 512, a sun of 2 x 2 texels of
radiance (160000, 150000, 130000), 30 degrees high: the window room's), nothing else. Every point of the
plane sees the whole upper hemisphere, so its radiance is 0.5 / pi x the irradiance, the sum over the
map's texels of radiance x cosine-weighted solid angle (scene_io.irradiance_from_above), written to
expected.json. The camera looks at a spot near the origin. Used by tools/race_cycles.py --analytic."""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "race"))
from scene_io import output_folder, Obj, irradiance_from_above, sky, sun_direction, write_exr, write_scene  # noqa: E402

WIDTH, HEIGHT, ALBEDO = 1024, 512, 0.5


def main():
    args = output_folder(__doc__)
    obj = Obj()
    f = 50.0
    obj.quad("plane", [(-f, 0, -f), (-f, 0, f), (f, 0, f), (f, 0, -f)])
    obj.write(args.out, "sky_plane", {"plane": {"Kd": (ALBEDO, ALBEDO, ALBEDO)}})
    texel = sky(WIDTH, HEIGHT, sun_direction(30, -20), (160000, 150000, 130000))
    write_exr(os.path.join(args.out, "sky.exr"), WIDTH, HEIGHT, texel)
    radiance = [ALBEDO / math.pi * e for e in irradiance_from_above(WIDTH, HEIGHT, texel)]
    with open(os.path.join(args.out, "expected.json"), "w") as out:
        json.dump({"radiance": radiance, "mean": sum(radiance) / 3}, out)
    write_scene(args.out, {"mesh": "sky_plane.obj",
                           "camera": {"eye": [0, 2, -4], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 5},
                           "environment": {"map": "sky.exr", "intensity": 1}})


if __name__ == "__main__":
    main()
