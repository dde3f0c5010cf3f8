#!/usr/bin/env python3
# The race against Blender's Cycles (issue 16): the same scene rendered by Cycles on the CPU and by
# fragpath, at several sample counts each, against one converged reference; prints error against process
# CPU time for both, and the CPU time each needs to reach the other's error. Not part of `make test`.
#
#   LP_NUM_THREADS is set from --threads for fragpath; Cycles gets the same thread count.
#   tools/race_cycles.py [--scene assets/cornell/cornell.json] [--size 128] [--max-depth 5]
#                        [--spp 16,64,256] [--reference-spp 8192] [--runs 3] [--threads 2]
#                        [--integrator nee] [--reference-integrator NAME] [--light-selection auto]
#                        [--caustics auto] [--reference FILE.pfm]
#
# Installs Debian's `blender` package when it is missing (apt-get, with sudo when not root). The scene is
# a fragpath scene file (an OBJ of Lambertian and emissive materials, and a camera); Cycles renders it
# through tools/race/cycles_render.py, which says how the two are matched. Times are whole-process CPU
# seconds (user + system of the child), the median of --runs runs (the two renderers alternating, run by
# run), less the median of 1-spp renders (start-up and scene set-up, for both); the error is the RMSE over pixels and channels against a fragpath render of
# --reference-spp samples (the Cycles image's mean against it is printed, to show the renderers agree).
import argparse
import json
import math
import os
import resource
import shutil
import statistics
import struct
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_pfm(path):
    with open(path, "rb") as f:
        f.readline()
        width, height = map(int, f.readline().split())
        endian = "<" if float(f.readline()) < 0 else ">"
        return list(struct.unpack("%s%df" % (endian, width * height * 3), f.read(12 * width * height)))


def timed(command, env=None):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def ensure_blender():
    if shutil.which("blender"):
        return
    sudo = [] if os.geteuid() == 0 else ["sudo"]
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(sudo + ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "blender"], check=True,
                   env=env)


def time_for_error(curve, error):
    """CPU time at which a (time, error) curve reaches `error`, log-log interpolated (extrapolated past
    its ends with the slope of the nearest segment)."""
    points = sorted(curve)
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if e1 <= error or (t1, e1) == points[-1]:
            slope = math.log(e1 / e0) / math.log(t1 / t0)
            return t0 * math.exp(math.log(error / e0) / slope)
    return float("nan")


def main():
    parser = argparse.ArgumentParser(description="error against CPU time, fragpath against Cycles")
    parser.add_argument("--scene", default=os.path.join(ROOT, "assets/cornell/cornell.json"))
    parser.add_argument("--fragpath", default=os.path.join(ROOT, "build/fragpath"))
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--max-depth", type=int, default=5)
    parser.add_argument("--spp", default="16,64,256")
    parser.add_argument("--reference-spp", type=int, default=8192)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--integrator", default="nee", help="fragpath's integrator in the race")
    parser.add_argument("--light-selection", default="auto", help="fragpath's, in the race and the reference")
    parser.add_argument("--caustics", default="auto", help="fragpath's, in the race (the reference keeps auto)")
    parser.add_argument("--reference", default=None,
                        help="an existing reference .pfm (a previous race's, printed at its end) instead of rendering one")
    parser.add_argument("--reference-integrator", default=None,
                        help="the reference's integrator (default: --integrator; bdpt converges faster on caustics)")
    args = parser.parse_args()
    ensure_blender()
    out = tempfile.mkdtemp(prefix="race_")
    scene = json.load(open(args.scene))
    obj = os.path.join(os.path.dirname(os.path.abspath(args.scene)), scene["mesh"])
    cam = scene["camera"]
    vec = lambda v: ",".join(repr(float(x)) for x in v)
    env = dict(os.environ, LP_NUM_THREADS=str(args.threads))
    size = "%dx%d" % (args.size, args.size)

    def fragpath(spp, seed, path, integrator=args.integrator, caustics=args.caustics):
        return [args.fragpath, "render", args.scene, "--size", size, "--spp", str(spp), "--max-depth",
                str(args.max_depth), "--seed", str(seed), "--integrator", integrator,
                "--light-selection", args.light_selection, "--caustics", caustics, "--samples-per-pass",
                "16", "--quiet", "-o", path]

    def cycles(spp, seed, path):
        # --python-exit-code: a failing script makes Blender exit non-zero (it exits 0 by default).
        return ["blender", "-b", "--factory-startup", "--python-exit-code", "1",
                "--python", os.path.join(ROOT, "tools/race/cycles_render.py"),
                "--", obj, path, str(args.size), str(args.size), str(spp), str(args.max_depth), str(args.threads),
                str(seed), vec(cam["eye"]), vec(cam["target"]), vec(cam.get("up", [0, 1, 0])), str(cam.get("fov", 45))]

    reference_path = os.path.join(out, "reference.pfm")
    reference_integrator = args.reference_integrator or args.integrator
    if args.reference:
        shutil.copyfile(args.reference, reference_path)
    else:
        subprocess.run(fragpath(args.reference_spp, 1000, reference_path, reference_integrator, "auto"),
                       check=True, env=env)
    reference = read_pfm(reference_path)

    def rmse(image):
        return math.sqrt(sum((a - b) ** 2 for a, b in zip(image, reference)) / len(reference))

    print("scene %s, %s, max depth %d, %d threads; fragpath %s, light selection %s, caustics %s; reference: "
          "%s" % (args.scene, size, args.max_depth, args.threads, args.integrator, args.light_selection,
                     args.caustics, args.reference or "fragpath %s, %d spp" % (reference_integrator,
                                                                             args.reference_spp)))
    commands = (("fragpath", fragpath), ("cycles", cycles))
    sample_counts = [int(s) for s in args.spp.split(",")]
    # Every measurement alternates the two renderers (fragpath, Cycles, fragpath, ...), so that a drift
    # in the machine's speed during the race falls on both alike. Set-up (start-up and scene set-up;
    # Blender's start is about a second) is the median CPU time of 1-spp renders, taken off the others,
    # so that the curves compare the sampling.
    setup = {name: [] for name, _ in commands}
    runs = {(name, spp): [] for name, _ in commands for spp in sample_counts}
    for run in range(args.runs):
        for name, command in commands:
            setup[name].append(timed(command(1, 100 + run, os.path.join(out, "%s_setup.pfm" % name)), env))
        for spp in sample_counts:
            for name, command in commands:
                path = os.path.join(out, "%s_%d_%d.pfm" % (name, spp, run))
                t = timed(command(spp, run + 1, path), env)
                image = read_pfm(path)
                runs[(name, spp)].append((t, rmse(image), sum(image) / sum(reference)))
    print("%-9s %6s %12s %12s %10s %14s" % ("renderer", "spp", "CPU s (med)", "minus set-up", "RMSE", "mean / ref"))
    curves = {}
    for name, _ in commands:
        base = statistics.median(setup[name])
        print("%-9s set-up (a 1-spp render) %.2f CPU s" % (name, base))
        curves[name] = []
        for spp in sample_counts:
            times, errors, means = zip(*runs[(name, spp)])
            t, e = statistics.median(times), math.sqrt(statistics.mean(x * x for x in errors))
            curves[name].append((max(t - base, 1e-3), e))
            print("%-9s %6d %12.2f %12.2f %10.5f %14.4f   (CPU s %s)" %
                  (name, spp, t, t - base, e, statistics.mean(means), " ".join("%.2f" % x for x in times)))
    for a, b in (("fragpath", "cycles"), ("cycles", "fragpath")):
        for t, e in curves[b]:
            ta = time_for_error(curves[a], e)
            print("%s needs %.2f CPU s (less set-up) for %s's RMSE %.5f (%s: %.2f s): %.2fx" %
                  (a, ta, b, e, b, t, ta / t))
    print("renders in", out)


if __name__ == "__main__":
    main()
