#!/usr/bin/env python3
# The environment-lit scene of docs/optimisation-log.md, entry 31 (not an asset: regenerate it): writes sky.hdr (256x128, a sky with a
# 4x4-texel sun of radiance (400, 300, 200)), scene.obj/.mtl (a 10x10 ground quad and three UV spheres,
# 6626 triangles, Kd 0.6) and env.json into the current directory.
import math
W, H = 256, 128
def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32: return bytes([0, 0, 0, 0])
    f, e = math.frexp(m)
    s = f * 256.0 / m
    return bytes([int(r * s), int(g * s), int(b * s), e + 128])
out = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (H, W))
for y in range(H):
    for x in range(W):
        t = y / H
        r, g, b = (0.3 + 0.4 * t, 0.45 + 0.3 * t, 0.8 - 0.2 * t) if y < H // 2 else (0.25, 0.2, 0.15)
        if 20 <= y < 24 and 60 <= x < 64: r, g, b = 400, 300, 200
        r *= 1 + 0.3 * math.sin(x * 0.2)
        out += rgbe(r, g, b)
open("sky.hdr", "wb").write(out)
v = []; f = []
def quad(a, b, c, d):
    n = len(v); v.extend([a, b, c, d]); f.append((n + 1, n + 2, n + 3)); f.append((n + 1, n + 3, n + 4))
quad((-5, 0, -5), (-5, 0, 5), (5, 0, 5), (5, 0, -5))
def sphere(cx, cy, cz, R, st=24, sl=48):
    base = len(v)
    for i in range(st + 1):
        th = math.pi * i / st
        for j in range(sl):
            ph = 2 * math.pi * j / sl
            v.append((cx + R * math.sin(th) * math.cos(ph), cy + R * math.cos(th), cz + R * math.sin(th) * math.sin(ph)))
    for i in range(st):
        for j in range(sl):
            a = base + i * sl + j + 1; b = base + i * sl + (j + 1) % sl + 1
            c = base + (i + 1) * sl + (j + 1) % sl + 1; d = base + (i + 1) * sl + j + 1
            if i > 0: f.append((a, c, b))
            if i < st - 1: f.append((a, d, c))
sphere(0, 1, 0, 1); sphere(-2.2, 0.6, 0.8, 0.6); sphere(2, 0.8, -0.5, 0.8)
with open("scene.obj", "w") as o:
    o.write("mtllib scene.mtl\nusemtl grey\n")
    for p in v: o.write("v %g %g %g\n" % p)
    for t in f: o.write("f %d %d %d\n" % t)
open("scene.mtl", "w").write("newmtl grey\nKd 0.6 0.6 0.6\n")
open("env.json", "w").write('{"mesh": "scene.obj", "camera": {"eye": [0, 2.5, -7], "target": [0, 0.8, 0], '
                            '"up": [0,1,0], "fov": 45}, "environment": {"map": "sky.hdr"}, '
                            '"render": {"spp": 16, "max_depth": 5}}\n')
