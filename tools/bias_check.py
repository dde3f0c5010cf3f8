#!/usr/bin/env python3
# The measurement behind issue 15's "done when": nee against bsdf at high sample counts in the scenes
# that showed its biases (a lamp 0.2 above a floor, the same under a grey sky, the Cornell box moved 10 m
# along x), and the moved box against the unmoved one. Each estimator renders SEEDS independent images;
# the spread of the block means over the seeds gives each block's standard error.
#
#   tools/bias_check.py [--fragpath build/fragpath] [--out DIR] [--size 48] [--seeds 4]
#                       [--nee-spp 2048] [--bsdf-spp 8192] [--block 12]
#
# Writes the scenes and the .pfm renders into DIR (default: a temporary directory) and prints, per
# comparison, the ratio of the whole-image means and the range of the block ratios. Set LP_NUM_THREADS.
import argparse
import math
import os
import struct
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def write_lamp_scene(out):
    with open(os.path.join(out, "lamp.mtl"), "w") as f:
        f.write("newmtl floor\nKd 0.7 0.7 0.7\nnewmtl lamp\nKd 0 0 0\nKe 5 5 5\n")
    with open(os.path.join(out, "lamp.obj"), "w") as f:
        # A 10 x 10 floor facing up and a 1 x 1 lamp 0.2 above it facing down (counter-clockwise fronts).
        f.write("mtllib lamp.mtl\nusemtl floor\nv -5 0 -5\nv -5 0 5\nv 5 0 5\nv 5 0 -5\nf 1 2 3 4\n")
        f.write("usemtl lamp\nv -0.5 0.2 -0.5\nv 0.5 0.2 -0.5\nv 0.5 0.2 0.5\nv -0.5 0.2 0.5\nf 5 6 7 8\n")
    camera = '"camera": {"eye": [0.3, 1.2, -1.6], "target": [0, 0, -0.2], "fov": 36}'
    with open(os.path.join(out, "lamp.json"), "w") as f:
        f.write('{"mesh": "lamp.obj", %s}\n' % camera)
    with open(os.path.join(out, "lamp_sky.json"), "w") as f:
        f.write('{"mesh": "lamp.obj", %s, "environment": {"color": [0.5, 0.5, 0.5]}}\n' % camera)


def write_moved_cornell(out, dx):
    lines = []
    with open(os.path.join(ROOT, "assets/cornell/cornell.obj")) as f:
        for line in f:
            if line.startswith("v "):
                x, y, z = map(float, line.split()[1:4])
                line = "v %.4f %.4f %.4f\n" % (x + dx, y, z)
            elif line.startswith("mtllib"):
                line = "mtllib %s\n" % os.path.join(ROOT, "assets/cornell/cornell.mtl")
            lines.append(line)
    with open(os.path.join(out, "cornell_moved.obj"), "w") as f:
        f.writelines(lines)
    with open(os.path.join(out, "cornell_moved.json"), "w") as f:
        f.write('{"mesh": "cornell_moved.obj", "camera": {"eye": [%g, 273, -800], "target": [%g, 273, 0], '
                '"up": [0, 1, 0], "fov": 39.3}}\n' % (278 + dx, 278 + dx))


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        endian = "<" if float(f.readline()) < 0 else ">"
        channels = 3 if kind == b"PF" else 1
        data = struct.unpack("%s%df" % (endian, width * height * channels), f.read(4 * width * height * channels))
    return width, height, [sum(data[channels * i:channels * i + channels]) / channels for i in range(width * height)]


def block_means(image, width, height, block):
    return [sum(image[(y + j) * width + x + i] for j in range(block) for i in range(block)) / block ** 2
            for y in range(0, height - block + 1, block) for x in range(0, width - block + 1, block)]


def mean_and_error(values):
    m = sum(values) / len(values)
    return m, math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1) / len(values))


def compare(a_paths, b_paths, block, label):
    a = [read_pfm(p) for p in a_paths]
    b = [read_pfm(p) for p in b_paths]
    width, height = a[0][0], a[0][1]
    wa, sa = mean_and_error([sum(img) / len(img) for _, _, img in a])
    wb, sb = mean_and_error([sum(img) / len(img) for _, _, img in b])
    ratio = wa / wb
    print("%s: image mean ratio %.4f +- %.4f" % (label, ratio, ratio * math.hypot(sa / wa, sb / wb)))
    ba = [block_means(img, width, height, block) for _, _, img in a]
    bb = [block_means(img, width, height, block) for _, _, img in b]
    means_b = [mean_and_error([x[k] for x in bb])[0] for k in range(len(bb[0]))]
    rows = []
    for k in range(len(means_b)):
        if means_b[k] <= 1e-3 * max(means_b):  # blocks that see nothing lit (the lamp's black back)
            continue
        ma, ea = mean_and_error([x[k] for x in ba])
        mb, eb = mean_and_error([x[k] for x in bb])
        rows.append((ma / mb, ma / mb * math.hypot(ea / ma, eb / mb)))
    worst = max(rows, key=lambda r: abs(r[0] - 1.0))
    print("  %d blocks of %dx%d: ratios %.4f..%.4f, the farthest from 1 %.4f +- %.4f" %
          (len(rows), block, block, min(r[0] for r in rows), max(r[0] for r in rows), worst[0], worst[1]))


def main():
    parser = argparse.ArgumentParser(description="nee against bsdf where issue 15 found biases")
    parser.add_argument("--fragpath", default=os.path.join(ROOT, "build/fragpath"))
    parser.add_argument("--out", default=None)
    parser.add_argument("--size", type=int, default=48)
    parser.add_argument("--seeds", type=int, default=4)
    parser.add_argument("--nee-spp", type=int, default=2048)
    parser.add_argument("--bsdf-spp", type=int, default=8192)
    parser.add_argument("--block", type=int, default=12)
    args = parser.parse_args()
    out = args.out or tempfile.mkdtemp(prefix="bias_check_")
    os.makedirs(out, exist_ok=True)
    write_lamp_scene(out)
    write_moved_cornell(out, 10000.0)

    def render(scene, integrator, spp, seed, name):
        path = os.path.join(out, name)
        command = [args.fragpath, "render"] + ([os.path.join(out, scene)] if scene else []) + [
            "--size", "%dx%d" % (args.size, args.size), "--spp", str(spp), "--integrator", integrator,
            "--seed", str(seed), "--quiet", "-o", path]
        subprocess.run(command, check=True)
        return path

    seeds = range(1, args.seeds + 1)
    for scene in ("lamp.json", "lamp_sky.json", "cornell_moved.json"):
        nee = [render(scene, "nee", args.nee_spp, s, "%s_nee_%d.pfm" % (scene, s)) for s in seeds]
        bsdf = [render(scene, "bsdf", args.bsdf_spp, 100 + s, "%s_bsdf_%d.pfm" % (scene, s)) for s in seeds]
        compare(nee, bsdf, args.block, "%s: nee / bsdf" % scene)
        if scene == "cornell_moved.json":
            origin = [render(None, "nee", args.nee_spp, 200 + s, "cornell_nee_%d.pfm" % s) for s in seeds]
            compare(nee, origin, args.block, "Cornell box moved 10 m / at the origin, nee")
    print("renders in", out)


if __name__ == "__main__":
    main()
