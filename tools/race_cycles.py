#!/usr/bin/env python3
# The race against Blender's Cycles (issues 16 and 35): the same scene rendered by Cycles on the CPU and
# by fragpath, at several sample counts each and at several path lengths, against converged references
# (Cycles', fragpath's or both); prints error against process CPU time for both, each renderer's mean
# against each reference, and the CPU time each needs to reach the other's error. Not part of `make test`.
#
# The race scenes (--scene NAME, or a list NAME,NAME; --suite: all of them; or --scene FILE.json):
#   cornell      assets/cornell/cornell.json: the Cornell box (published data, one lamp)
#   glass        assets/cornell_spheres/cornell_spheres.json: a smooth glass and a gold GGX sphere
#   gltf         a textured glTF model under an HDR sky with a sun (tools/make_race_gltf.py)
#   many-lights  assets/many_lights/many_lights.json: a hall of 112 small lamps
#   window       a closed room lit by sky and sun through a window (tools/make_window_room.py)
#   mesh         a Cornell room around a displaced blob of 81,920 triangles (tools/make_mesh_room.py)
#   checker      assets/cornell_checker/cornell_checker.json: the Cornell box with a textured floor (not in
#                --suite)
# Generated scenes are written once into build/race_scenes/NAME/ (--scene-dir).
#
# The lead's race, on a quiet machine: each scene at max depth 64, 12 and 5 (the defaults), 256x256,
# 16, 64 and 256 spp, 3 runs, against Cycles' and fragpath's 4096-spp references; one command a scene:
#   tools/race_cycles.py --scene cornell     --reference-renderer both --out build/race --json race_cornell.json
#   tools/race_cycles.py --scene glass       --reference-renderer both --out build/race --json race_glass.json
#   tools/race_cycles.py --scene gltf        --reference-renderer both --out build/race --json race_gltf.json
#   tools/race_cycles.py --scene many-lights --reference-renderer both --out build/race --json race_many_lights.json
#   tools/race_cycles.py --scene window      --reference-renderer both --out build/race --json race_window.json
#   tools/race_cycles.py --scene mesh        --reference-renderer both --out build/race --json race_mesh.json
#   tools/race_cycles.py --suite --reference-renderer both --out build/race --json race.json   # the six in one go
#   tools/race_cycles.py --analytic --json analytic.json   # each renderer's offset from a closed form
#   tools/race_cycles.py --rows race.json                   # BENCHMARKS.md's table rows from a --json file
# On the glTF scene Cycles cannot express fragpath's material exactly (tools/race/cycles_render.py):
# read its "own" rows. The second table (the earlier rows' settings):
#   tools/race_cycles.py --scene cornell --size 128 --max-depth 5 --reference-renderer fragpath \
#                        --reference-spp 8192 [--fragpath-args "--samples-per-pass 16"]
# Before racing a new scene, check that the two renderers agree (means and block means with their
# standard errors, and a PNG of both side by side to look at), at a small size:
#   tools/race_cycles.py --check --suite --max-depth 64 --check-size 32 --check-spp 512
# A quick end-to-end run (a loaded machine): --runs 1 --size 128 --spp 16,64 --max-depth 64 --reference-spp 1024
#
# fragpath runs its default command (`fragpath render SCENE --size --spp --max-depth --seed -o`): no
# --samples-per-pass, integrator, light selection or caustics unless given (--integrator, --light-selection,
# --caustics, or anything with --fragpath-args "..."). LP_NUM_THREADS is set from --threads; Cycles gets
# the same thread count. Cycles renders the scene file through tools/race/cycles_render.py, which says how
# the two are matched. Times are whole-process CPU seconds (user + system of the child), the median of
# --runs runs (the two renderers alternating, run by run), less the median of 1-spp renders (start-up and
# scene set-up, for both); the error is the RMSE over pixels and channels against each reference, and
# with --reference-renderer both also against each renderer's own reference ("own": convergence alone,
# free of the two renderers' small differences). --json FILE writes every figure (every run) for
# BENCHMARKS.md's rows. Installs Debian's `blender` package when it is missing.
import argparse
import datetime
import json
import math
import os
import resource
import shlex
import shutil
import statistics
import struct
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# name: (what it is, scene file in the repository, or the generator that writes scene.json into a folder)
SCENES = {
    "cornell": ("the Cornell box (one lamp)", "assets/cornell/cornell.json", None),
    "glass": ("Cornell room with a smooth glass and a gold GGX sphere", "assets/cornell_spheres/cornell_spheres.json",
              None),
    "gltf": ("a textured glTF model under an HDR sky with a sun", None, "tools/make_race_gltf.py"),
    "many-lights": ("a hall of 112 small lamps", "assets/many_lights/many_lights.json", None),
    "window": ("a closed room lit by sky and sun through a window", None, "tools/make_window_room.py"),
    "mesh": ("a Cornell room around a displaced blob of 81,920 triangles", None, "tools/make_mesh_room.py"),
    "checker": ("the Cornell box with a checker-textured floor", "assets/cornell_checker/cornell_checker.json",
                None),
}
# --suite: the scenes of issue 35 (the checker floor is the Cornell box's story again)
SUITE = ("cornell", "glass", "gltf", "many-lights", "window", "mesh")

# The analytic scene (tools/make_lamp_plane.py): a Lambertian plane of albedo 0.5 under a one-sided square
# lamp of radiance 1, side 2, 1 above; under the lamp's centre its radiance is 0.5 x the form factor
# (tests/render/analytic_lamp.h, lampFormFactor).
ANALYTIC_GENERATOR = "tools/make_lamp_plane.py"
# And a grey plane under a sky with a small bright sun (tools/make_sky_plane.py, which writes the
# expected radiance).
SKY_PLANE_GENERATOR = "tools/make_sky_plane.py"


def corner_form_factor(x, y):
    # Differential area to a parallel rectangle with one corner above it (Howell's catalogue), as
    # tests/render/analytic_lamp.h cornerFormFactor.
    sx, sy = math.sqrt(1 + x * x), math.sqrt(1 + y * y)
    return (x / sx * math.atan(y / sx) + y / sy * math.atan(x / sy)) / (2 * math.pi)


ANALYTIC_RADIANCE = 0.5 * 4 * corner_form_factor(1.0, 1.0)  # 0.5 x 0.554126 = 0.277063


def read_pfm(path):
    with open(path, "rb") as f:
        f.readline()
        width, height = map(int, f.readline().split())
        endian = "<" if float(f.readline()) < 0 else ">"
        return list(struct.unpack("%s%df" % (endian, width * height * 3), f.read(12 * width * height)))


def timed(command, env=None):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    result = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if result.returncode != 0:
        sys.stderr.write(result.stderr.decode(errors="replace")[-4000:])
        raise SystemExit("failed (%d): %s" % (result.returncode, " ".join(map(shlex.quote, command))))
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if b"--environment none keeps it dark" in result.stderr:
        # fragpath's default light (docs/scene-files.md, "Default camera and light"), which Cycles would not have.
        raise SystemExit("fragpath added its default light to the scene, which Cycles does not: give the scene "
                         "file light of its own, or --fragpath-args \"--environment none\"\n" +
                         result.stderr.decode(errors="replace"))
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def ensure_blender():
    """Debian's blender, and python3-numpy, which its glTF importer needs (Debian's blender does not
    depend on it)."""
    missing = [] if shutil.which("blender") else ["blender"]
    if not os.path.exists("/usr/lib/python3/dist-packages/numpy"):
        missing.append("python3-numpy")
    if not missing:
        return
    sudo = [] if os.geteuid() == 0 else ["sudo"]
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(sudo + ["apt-get", "install", "-y", "-qq", "--no-install-recommends"] + missing, check=True,
                   env=env)


def time_for_error(curve, error):
    """CPU time at which a (time, error) curve reaches `error`, log-log interpolated (extrapolated past
    its ends with the slope of the nearest segment)."""
    points = sorted(curve)
    if len(points) < 2:
        return float("nan")
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if e1 <= error or (t1, e1) == points[-1]:
            if t1 <= t0 or e0 <= 0 or e1 <= 0 or e1 == e0:
                return float("nan")  # times too short to tell apart (less set-up), or no slope
            slope = math.log(e1 / e0) / math.log(t1 / t0)
            return t0 * math.exp(math.log(error / e0) / slope)
    return float("nan")


def rmse(image, reference):
    return math.sqrt(sum((a - b) ** 2 for a, b in zip(image, reference)) / len(reference))


def scene_file(name, scene_dir):
    """The scene file for a race scene's name (generating it when needed), or the path given."""
    if name not in SCENES:
        if not os.path.exists(name):
            raise SystemExit("no scene %r: a file, or one of %s" % (name, ", ".join(SCENES)))
        return os.path.abspath(name)
    _, path, generator = SCENES[name]
    if path:
        return os.path.join(ROOT, path)
    return generated(generator, os.path.join(scene_dir, name))


def generated(generator, folder):
    path = os.path.join(folder, "scene.json")
    if not os.path.exists(path):
        os.makedirs(folder, exist_ok=True)
        subprocess.run([sys.executable, os.path.join(ROOT, generator), "--out", folder], check=True)
    return path


def commit():
    result = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    return result.stdout.strip()


def load_average():
    with open("/proc/loadavg") as f:
        return [float(x) for x in f.read().split()[:3]]


class Renderers:
    """The two command lines, for one scene and path length."""

    def __init__(self, args, scene, depth, size, out):
        self.args, self.scene, self.depth, self.size, self.out = args, scene, depth, size, out
        self.env = dict(os.environ, LP_NUM_THREADS=str(args.threads))
        self.fragpath_extra = []  # arguments a scene needs (the analytic scene's --environment none)

    def fragpath(self, spp, seed, path, extra=None):
        command = [self.args.fragpath, "render", self.scene, "--size", "%dx%d" % (self.size, self.size), "--spp",
                   str(spp), "--max-depth", str(self.depth), "--seed", str(seed), "--quiet", "-o", path]
        for flag in ("integrator", "light_selection", "caustics"):
            value = getattr(self.args, flag)
            if value:
                command += ["--" + flag.replace("_", "-"), value]
        return command + self.fragpath_extra + shlex.split(self.args.fragpath_args) + (extra or [])

    def cycles(self, spp, seed, path):
        job = path + ".job.json"
        with open(job, "w") as f:
            json.dump({"scene": self.scene, "out": path, "width": self.size, "height": self.size, "spp": spp,
                       "max_depth": self.depth, "threads": self.args.threads, "seed": seed}, f)
        # --python-exit-code: a failing script makes Blender exit non-zero (it exits 0 by default).
        return ["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python",
                os.path.join(ROOT, "tools/race/cycles_render.py"), "--", job]

    def command(self, renderer, spp, seed, path):
        return self.fragpath(spp, seed, path) if renderer == "fragpath" else self.cycles(spp, seed, path)

    def render(self, renderer, spp, seed, name):
        path = os.path.join(self.out, name + ".pfm")
        return timed(self.command(renderer, spp, seed, path), self.env), read_pfm(path), path


def references(args, r, label):
    """{name: image} for the references asked for, rendered (or the given --reference file)."""
    wanted = ["cycles", "fragpath"] if args.reference_renderer == "both" else [args.reference_renderer]
    out = {}
    for renderer in wanted:
        if args.reference:
            out[renderer] = (read_pfm(args.reference), args.reference, "given")
            continue
        extra = ["--integrator", args.reference_integrator] if args.reference_integrator else []
        integrator = "_" + args.reference_integrator if args.reference_integrator and renderer == "fragpath" else ""
        path = os.path.join(r.out, "%s_%d_reference_%s%s_%d.pfm" % (label, r.size, renderer, integrator,
                                                                   args.reference_spp))
        what = "%s %d spp" % (renderer, args.reference_spp)
        if os.path.exists(path):
            # A reference of the same scene, depth, size, renderer and samples in --out: a rerun reuses it.
            print("  reference: %s, reused %s" % (what, path), flush=True)
        else:
            command = r.fragpath(args.reference_spp, 1000, path, extra) if renderer == "fragpath" else \
                r.cycles(args.reference_spp, 1000, path)
            seconds = timed(command, r.env)
            print("  reference: %s, %.1f CPU s -> %s" % (what, seconds, path), flush=True)
        out[renderer] = (read_pfm(path), path, what)
    return out


def race(args, name, scene, depth, out):
    label = "%s_d%d" % (name, depth)
    r = Renderers(args, scene, depth, args.size, out)
    print("\n== %s (%s), %dx%d, max depth %d, %d threads; fragpath: %s" %
          (name, scene, args.size, args.size, depth, args.threads,
           "fragpath " + " ".join(r.fragpath("N", "S", "OUT")[1:])), flush=True)
    refs = references(args, r, label)
    renderers = ("fragpath", "cycles")
    sample_counts = [int(s) for s in args.spp.split(",")]
    load_before = load_average()
    # Every measurement alternates the two renderers (fragpath, Cycles, fragpath, ...), so that a drift in
    # the machine's speed during the race falls on both alike. Set-up (start-up and scene set-up;
    # Blender's start is about a second) is the median CPU time of 1-spp renders, taken off the others,
    # so that the curves compare the sampling.
    setup = {n: [] for n in renderers}
    runs = []
    for run in range(args.runs):
        for n in renderers:
            setup[n].append(r.render(n, 1, 100 + run, "%s_%s_setup" % (label, n))[0])
        for spp in sample_counts:
            for n in renderers:
                seconds, image, _ = r.render(n, spp, run + 1, "%s_%s_%d_%d" % (label, n, spp, run))
                errors = {ref: rmse(image, refs[ref][0]) for ref in refs}
                ratios = {ref: sum(image) / sum(refs[ref][0]) for ref in refs}
                if len(refs) == 2:
                    errors["own"] = rmse(image, refs[n][0])
                runs.append({"renderer": n, "spp": spp, "run": run, "cpu_s": seconds, "rmse": errors,
                             "mean_over_reference": ratios})
    kinds = list(refs) + (["own"] if len(refs) == 2 else [])
    summary, curves = {}, {k: {} for k in kinds}
    print("%-9s %6s %11s %12s  %s" % ("renderer", "spp", "CPU s (med)", "minus set-up",
                                      "  ".join("RMSE(%s) mean/ref(%s)" % (k, k) if k != "own" else "RMSE(own)"
                                                for k in kinds)))
    for n in renderers:
        base = statistics.median(setup[n])
        print("%-9s set-up (a 1-spp render) %.2f CPU s" % (n, base))
        summary[n] = {"setup_cpu_s": base, "setup_runs": setup[n], "spp": {}}
        for spp in sample_counts:
            mine = [x for x in runs if x["renderer"] == n and x["spp"] == spp]
            t = statistics.median(x["cpu_s"] for x in mine)
            errors = {k: math.sqrt(statistics.mean(x["rmse"][k] ** 2 for x in mine)) for k in kinds}
            ratios = {k: statistics.mean(x["mean_over_reference"][k] for x in mine) for k in refs}
            summary[n]["spp"][spp] = {"cpu_s": t, "cpu_s_less_setup": t - base, "rmse": errors,
                                      "mean_over_reference": ratios}
            for k in kinds:
                curves[k].setdefault(n, []).append((max(t - base, 1e-3), errors[k]))
            print("%-9s %6d %11.2f %12.2f  %s   (CPU s %s)" %
                  (n, spp, t, t - base, "  ".join("%9.5f %11.5f" % (errors[k], ratios[k]) if k != "own" else
                                                  "%9.5f" % errors[k] for k in kinds),
                   " ".join("%.2f" % x["cpu_s"] for x in mine)))
    crossings = []
    for k in kinds:
        for a, b in (("fragpath", "cycles"), ("cycles", "fragpath")):
            for spp, (t, e) in zip(sample_counts, curves[k][b]):
                ta = time_for_error(curves[k][a], e)
                crossings.append({"reference": k, "renderer": a, "against": b, "spp": spp, "error": e,
                                  "cpu_s": ta, "against_cpu_s": t, "ratio": ta / t})
                print("[%s] %s needs %.2f CPU s (less set-up) for %s's RMSE %.5f at %d spp (%s: %.2f s): %.2fx" %
                      (k, a, ta, b, e, spp, b, t, ta / t))
    return {"scene": name, "scene_file": scene, "max_depth": depth, "size": args.size, "threads": args.threads,
            "runs": args.runs, "spp": sample_counts, "fragpath_command": r.fragpath("N", "S", "OUT"),
            "references": {k: {"path": v[1], "what": v[2]} for k, v in refs.items()},
            "load_average_before": load_before, "load_average_after": load_average(),
            "summary": summary, "crossings": crossings, "every_run": runs}


def analytic(args, out):
    """Each renderer's mean radiance over a spot where the radiance is known, against that value: the
    plane under a square lamp (a closed form) and the plane under a sky with a small sun (a sum over
    the map's texels)."""
    lamp = generated(ANALYTIC_GENERATOR, os.path.join(args.scene_dir, "analytic"))
    sky = generated(SKY_PLANE_GENERATOR, os.path.join(args.scene_dir, "analytic_sky"))
    with open(os.path.join(os.path.dirname(sky), "expected.json")) as f:
        sky_radiance = json.load(f)["mean"]
    # fragpath's default light takes the dim lamp over an open plane for glowing detail and adds its
    # studio environment; the closed form has no other light.
    cases = (("lamp", "a plane under a square lamp", lamp, ANALYTIC_RADIANCE, ["--environment", "none"]),
             ("sky", "a plane under a sky with a small sun", sky, sky_radiance, []))
    size, spp = args.analytic_size, args.analytic_spp
    result = {"size": size, "spp": spp, "cases": []}
    for key, what, scene, expected, extra in cases:
        r = Renderers(args, scene, 5, size, out)
        r.fragpath_extra = extra
        print("analytic: %s (%s), %dx%d, %d spp, max depth 5; expected %.6f" % (what, scene, size, size, spp,
                                                                                expected))
        case = {"case": key, "what": what, "scene_file": scene, "expected": expected, "renderers": {}}
        for n in ("fragpath", "cycles"):
            seconds, image, path = r.render(n, spp, 7, "analytic_%s_%s" % (key, n))
            pixels = [sum(image[i:i + 3]) / 3 for i in range(0, len(image), 3)]
            mean = statistics.mean(pixels)
            # Standard error as if the pixels were independent estimates (fragpath spreads its samples
            # as blue noise across pixels, which makes its true error smaller: then an upper bound).
            error = statistics.stdev(pixels) / math.sqrt(len(pixels))
            offset = mean / expected - 1
            print("  %-9s mean %.6f +- %.6f (1 sigma): %+.3f%% +- %.3f%%  (%.1f CPU s)" %
                  (n, mean, error, 100 * offset, 100 * error / expected, seconds))
            case["renderers"][n] = {"mean": mean, "standard_error": error, "offset": offset, "cpu_s": seconds,
                                    "image": path, "command": r.command(n, spp, 7, path)}
        result["cases"].append(case)
    return result


def check(args, name, scene, depth, out):
    """Both renderers at a small size and modest spp, twice each (two seeds): the whole image's mean and
    each block's, Cycles' over fragpath's, with standard errors from the two renders' difference (which
    holds the noise and none of the image's detail); PNGs to look at."""
    sys.path.insert(0, os.path.join(ROOT, "tools/race"))
    from scene_io import write_png
    size, spp, blocks = args.check_size, args.check_spp, args.check_blocks
    r = Renderers(args, scene, depth, size, out)
    images = {}
    for n in ("fragpath", "cycles"):
        images[n] = [r.render(n, spp, seed, "check_%s_d%d_%s_%d" % (name, depth, n, seed))[1] for seed in (11, 12)]
    # One PNG, fragpath left and Cycles right, each the mean of its two renders, enlarged to 256 rows.
    zoom = max(1, 256 // size)
    means = [[0.5 * (a + b) for a, b in zip(*images[n])] for n in ("fragpath", "cycles")]
    side = [means[(x // zoom) // size][3 * ((y // zoom) * size + (x // zoom) % size) + c]
            for y in range(size * zoom) for x in range(2 * size * zoom) for c in range(3)]
    png = os.path.join(out, "check_%s_d%d.png" % (name, depth))
    write_png(png, 2 * size * zoom, size * zoom, side)
    print("\n== check %s (%s), %dx%d, 2 x %d spp, max depth %d: Cycles / fragpath, mean +- 1 sigma; %s (fragpath | Cycles)" %
          (name, scene, size, size, spp, depth, png))

    def region(pair, x0, y0, x1, y1):
        """The region's mean over both renders, and its standard error."""
        indices = [3 * (y * size + x) + c for y in range(y0, y1) for x in range(x0, x1) for c in range(3)]
        first, second = [pair[0][i] for i in indices], [pair[1][i] for i in indices]
        pixels = len(indices) // 3
        mean = 0.5 * (statistics.mean(first) + statistics.mean(second))
        difference = [sum(first[i:i + 3]) / 3 - sum(second[i:i + 3]) / 3 for i in range(0, len(first), 3)]
        return mean, 0.5 * statistics.pstdev(difference) / math.sqrt(pixels)

    def compare(x0, y0, x1, y1):
        (mf, ef), (mc, ec) = (region(images[n], x0, y0, x1, y1) for n in ("fragpath", "cycles"))
        ratio = mc / mf if mf > 0 else float("nan")
        sigma = ratio * math.hypot(ef / mf, ec / mc) if mf > 0 and mc > 0 else float("nan")
        return mf, mc, ratio, sigma

    mf, mc, ratio, sigma = compare(0, 0, size, size)
    print("whole image: fragpath %.5f, Cycles %.5f, ratio %.4f +- %.4f" % (mf, mc, ratio, sigma))
    step = size // blocks
    rows, worst = [], 0.0
    for by in reversed(range(blocks)):  # the image's top row first
        cells = []
        for bx in range(blocks):
            _, _, q, s = compare(bx * step, by * step, (bx + 1) * step, (by + 1) * step)
            cells.append("%.3f+-%.3f" % (q, s))
            if s == s and s > 0:
                worst = max(worst, abs(q - 1) / s)
        rows.append("  " + " ".join(cells))
    print("blocks (%dx%d, top row first):\n%s\nlargest |ratio - 1| / sigma over blocks: %.1f" %
          (blocks, blocks, "\n".join(rows), worst))
    return {"scene": name, "max_depth": depth, "size": size, "spp": spp, "fragpath_mean": mf, "cycles_mean": mc,
            "ratio": ratio, "sigma": sigma, "largest_block_z": worst}


def rows(path):
    """BENCHMARKS.md table rows from a --json file: per race and reference, each sample count's CPU
    seconds less set-up, RMSE and mean / reference for both renderers, and fragpath's CPU time for
    Cycles' error over Cycles'."""
    report = json.load(open(path))
    print("<!-- %s, commit %s, %d threads: tools/race_cycles.py %s -->" %
          (report["date"], report["commit"], report["threads"], " ".join(report["argv"])))
    print("| scene | depth | reference | spp | fragpath CPU s | fragpath RMSE | fragpath mean / ref | Cycles CPU s | "
          "Cycles RMSE | Cycles mean / ref | fragpath's CPU time for Cycles' error, over Cycles' |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for race in report["races"]:
        for kind in list(race["references"]) + (["own"] if len(race["references"]) == 2 else []):
            for spp in race["spp"]:
                f, c = (race["summary"][n]["spp"][str(spp)] for n in ("fragpath", "cycles"))
                crossing = next(x for x in race["crossings"] if x["reference"] == kind and
                                x["renderer"] == "fragpath" and x["spp"] == spp)
                ratio = lambda x: "%.4f" % x["mean_over_reference"][kind] if kind != "own" else "-"
                print("| %s | %d | %s | %d | %.2f | %.5f | %s | %.2f | %.5f | %s | %.2fx |" %
                      (race["scene"], race["max_depth"], race["references"].get(kind, {}).get("what", "own"), spp,
                       f["cpu_s_less_setup"], f["rmse"][kind], ratio(f), c["cpu_s_less_setup"], c["rmse"][kind],
                       ratio(c), crossing["ratio"]))
    if "analytic" in report:
        a = report["analytic"]
        for case in a["cases"]:
            for n, r in case["renderers"].items():
                print("| analytic: %s, %dx%d, %d spp | %s | mean %.6f +- %.6f | expected %.6f | %+.3f%% |" %
                      (case["what"], a["size"], a["size"], a["spp"], n, r["mean"], r["standard_error"],
                       case["expected"], 100 * r["offset"]))


def main():
    parser = argparse.ArgumentParser(description="error against CPU time, fragpath against Cycles")
    parser.add_argument("--scene", default="cornell",
                        help="a race scene's name (%s), a list of them, or a fragpath scene file" % ", ".join(SCENES))
    parser.add_argument("--suite", action="store_true", help="the race scenes: " + ", ".join(SUITE))
    parser.add_argument("--scene-dir", default=os.path.join(ROOT, "build/race_scenes"),
                        help="where generated scenes are written (once)")
    parser.add_argument("--fragpath", default=os.path.join(ROOT, "build/fragpath"))
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--max-depth", default="64,12,5", help="a list: each path length is raced in turn")
    parser.add_argument("--spp", default="16,64,256")
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--reference-renderer", choices=("cycles", "fragpath", "both"), default="cycles")
    parser.add_argument("--reference-integrator", default=None, help="fragpath's reference's integrator")
    parser.add_argument("--reference", default=None,
                        help="an existing reference .pfm (one scene and depth) instead of rendering one")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--integrator", default=None, help="fragpath's, in the race (default: its default)")
    parser.add_argument("--light-selection", default=None, help="fragpath's (default: its default)")
    parser.add_argument("--caustics", default=None, help="fragpath's (default: its default)")
    parser.add_argument("--fragpath-args", default="", help="more arguments for fragpath, e.g. \"--sampler independent\"")
    parser.add_argument("--analytic", action="store_true",
                        help="only the analytic scenes (a plane under a square lamp, a plane under a sky with a small sun): "
                             "each renderer's offset from the known radiance")
    parser.add_argument("--analytic-size", type=int, default=32)
    parser.add_argument("--analytic-spp", type=int, default=16384)
    parser.add_argument("--check", action="store_true",
                        help="only compare the two renderers' images (means, block means, PNGs), no race")
    parser.add_argument("--check-size", type=int, default=64)
    parser.add_argument("--check-spp", type=int, default=256)
    parser.add_argument("--check-blocks", type=int, default=4)
    parser.add_argument("--out", default=None,
                        help="where the renders go (default: a new temporary folder); references already there "
                             "(same scene, depth, size, renderer, spp) are reused: remove fragpath's after changing fragpath")
    parser.add_argument("--json", default=None, help="write every figure to this file")
    parser.add_argument("--rows", default=None, metavar="FILE.json",
                        help="print BENCHMARKS.md's table rows from a --json file, and nothing else")
    args = parser.parse_args()
    if args.rows:
        return rows(args.rows)
    ensure_blender()
    out = args.out or tempfile.mkdtemp(prefix="race_")
    os.makedirs(out, exist_ok=True)
    report = {"date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
              "commit": commit(), "threads": args.threads, "argv": sys.argv[1:], "races": []}
    if args.analytic:
        report["analytic"] = analytic(args, out)
    else:
        names = list(SUITE) if args.suite else args.scene.split(",")
        depths = [int(d) for d in args.max_depth.split(",")]
        if args.reference and (len(names) > 1 or len(depths) > 1 or args.reference_renderer == "both"):
            raise SystemExit("--reference is one image: give one scene, one depth and one reference renderer")
        for given in names:
            scene = scene_file(given, args.scene_dir)
            name = given if given in SCENES else os.path.splitext(os.path.basename(given))[0]
            for depth in depths:
                if args.check:
                    report.setdefault("checks", []).append(check(args, name, scene, depth, out))
                    continue
                report["races"].append(race(args, name, scene, depth, out))
                if args.json:  # written as it goes: a long suite keeps what it has measured
                    with open(args.json, "w") as f:
                        json.dump(report, f, indent=1)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(report, f, indent=1)
    print("renders in", out)


if __name__ == "__main__":
    main()
