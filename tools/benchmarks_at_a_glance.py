#!/usr/bin/env python3
"""BENCHMARKS.md's "At a glance" table from one run: measures what each row quotes, with the commands
of the section the row links to, and rewrites the table between <!-- at-a-glance:begin --> and
<!-- at-a-glance:end -->, stamped with the commit, the date, the machine (CPU model, cores, Mesa) and
the load average, so that no figure is quoted after the code it measured changed.

    tools/benchmarks.sh [--quick] [--runs N] [--only ROW,ROW] [--race-json FILE] [--no-write]
    python3 tools/benchmarks_at_a_glance.py --from-json build/benchmarks/at_a_glance.json   # table only

Each figure is the median over --runs invocations (min-max beside it where it moves). The machine is
often shared: CPU seconds are given beside wall seconds, and paths per CPU-second hold up under load
where paths per wall second do not (BENCHMARKS.md, "Method"). Rows whose measurement takes hours (the
race against Cycles) or does not depend on the machine (the BVH's SAH cost) are read from their
source, a JSON file that tool wrote (--race-json) or the record below, and their cell names the
source's commit and date. --quick measures everything at toy sizes, to check that the script works;
its figures mean nothing and it never rewrites BENCHMARKS.md unless --write-quick is given.

Every measurement is written to build/benchmarks/at_a_glance.json (--json), which --from-json turns
into the table again without measuring."""
import argparse
import csv
import datetime
import json
import math
import os
import re
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from race_cycles import read_pfm  # noqa: E402
from startup_times import sample_models  # noqa: E402
BEGIN = "<!-- at-a-glance:begin -->"
END = "<!-- at-a-glance:end -->"

# Rows not measured by this script: the figure, where it comes from, its commit and date.
RECORDED = {
    "race": {
        "figure": "**0.33x / 0.42x / 0.47x** on the Cornell box, 0.48x / 0.45x / 0.40x in a hall of 112 lamps, "
                  "0.45x / 0.46x / 0.46x in a room lit through a window; 0.68-0.74x with glass and gold spheres, "
                  "0.60-0.78x on a textured glTF model (each against its own reference), 0.71-0.95x around an "
                  "81,920-triangle mesh (the target of 0.5x met on three scenes of six)",
        "source": "tools/race_cycles.py --suite, 3 alternating runs on a quiet machine",
        "commit": "e37632f", "date": "2026-12-06",
    },
    "bvh_quality": {
        "figure": "within 0.5 % or better on every suite scene (SAH cost, which does not depend on the machine; "
                  "`SahQuality.BinnedWithinTwoPercentOfSweepOnRoomScenes` asserts 2 %)",
        "source": "the tree-quality table", "commit": "the builder of 2026-12-01", "date": "2026-12-01",
    },
}

SECTIONS = {
    "cornell": "[Throughput](#throughput-the-cornell-box-and-the-large-spheres)",
    "sphere1m": "[Throughput](#throughput-the-cornell-box-and-the-large-spheres), "
                "[Suite](#suite-seven-scenes-from-32-to-1000000-triangles)",
    "sphere1m_first": "[Suite](#suite-seven-scenes-from-32-to-1000000-triangles)",
    "glb": "[glTF: a million triangles](#gltf-a-million-triangles-from-a-glb)",
    "instancing": "[Instancing](#instancing-two-levels-against-a-flattened-scene)",
    "first_frame": "[Time to first frame](#time-to-first-frame-cold-vs-warm-shader-cache)",
    "gltf_startup": "[Start-up on real models](#start-up-on-real-models)",
    "sampler": "[Samplers](#samplers-error-against-samples)",
    "race": "[The race against Cycles](#the-race-against-cycles)",
    "caustics": "[Caustics by light paths](#caustics-by-light-paths)",
    "light_tree": "[Samplers](#samplers-error-against-samples)",
    "denoisers": "[Denoisers](#denoisers-error-against-a-converged-render)",
    "bvh_quality": "[Tree quality](#tree-quality-binned-against-full-sweep-sah)",
    "caustic_study": "[BDPT vs NEE](#bdpt-vs-nee-on-a-caustic-scene)",
    "viewer": "[Viewer](#viewer-frame-time-at-the-default-window-size)",
    "realtime": "[Real time](#real-time-temporal-reuse-against-brute-force)",
    "study": "[docs/study.md](docs/study.md#the-run-in-docsstudy)",
}

ORDER = ["cornell", "sphere1m", "sphere1m_first", "glb", "instancing", "first_frame", "gltf_startup", "sampler",
         "race", "caustics", "light_tree", "denoisers", "bvh_quality", "caustic_study", "viewer", "realtime",
         "study"]


# ----------------------------------------------------------------------------------------------------------
# Running fragpath and reading what it writes


class Runner:
    def __init__(self, fragpath, work, quick, runs, log):
        self.fragpath = fragpath
        self.work = work
        self.quick = quick
        self.runs = runs
        self.log = log

    def path(self, *parts):
        p = os.path.join(self.work, *parts)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        return p

    def run(self, args, env=None, prefix=(), timeout=3600):
        command = list(prefix) + [self.fragpath] + [str(a) for a in args]
        self.log("  $ " + " ".join(command))
        full_env = dict(os.environ)
        full_env.update(env or {})
        started = time.time()
        r = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=full_env,
                           timeout=timeout, cwd=ROOT)
        if r.returncode != 0:
            raise RuntimeError("%s exited %d:\n%s" % (" ".join(command), r.returncode, r.output[-2000:]))
        self.log("    (%.1f s)" % (time.time() - started))
        return r.stdout

    def json(self, args, name, **kw):
        out = self.path("json", name + ".json")
        if os.path.exists(out):
            os.remove(out)
        self.run(list(args) + ["--json", out], **kw)
        with open(out) as f:
            return json.load(f)

    def render(self, args, name):
        """fragpath render ARGS -o NAME.pfm --json: the stats and the image."""
        image = self.path("images", name + ".pfm")
        stats = self.json(["render"] + list(args) + ["--quiet", "-o", image], name)
        return stats, read_pfm(image)


def rmse(a, b, mask=None):
    total, count = 0.0, 0
    for i in range(len(a)):
        if mask is not None and not mask[i // 3]:
            continue
        d = a[i] - b[i]
        total += d * d
        count += 1
    return math.sqrt(total / count)


def variance_of_mean(a, b):
    """The variance of one image's pixel values, from two images of independent seeds: half the mean
    squared difference."""
    return sum((x - y) ** 2 for x, y in zip(a, b)) / (2 * len(a))


def med(values):
    return statistics.median(values)


def span(values, fmt):
    """'median (min-max)', or the value alone when there is one."""
    if len(values) == 1:
        return fmt % values[0]
    return (fmt + " (" + fmt + "-" + fmt + ")") % (med(values), min(values), max(values))


# ----------------------------------------------------------------------------------------------------------
# The measurements, one per row. Each returns a dict of figures (and the commands it ran).


def measure_cornell(r):
    size = ["--size", "64x64", "--spp", "1", "--runs", "1"] if r.quick else []
    shader, native, ratio = [], [], []
    for i in range(r.runs):
        d = r.json(["bench", "--native"] + size, "cornell_%d" % i)
        shader.append(d["summary"]["paths_per_cpu_second"]["median"])
        native.append(d["native"]["paths_per_cpu_second"]["median"])
        ratio.append(d["native"]["gpu_over_native"])
    return {"command": "fragpath bench --native" + (" " + " ".join(size) if size else ""),
            "shader_paths_per_cpu_second": shader, "native_paths_per_cpu_second": native, "gpu_over_native": ratio}


def measure_suite(r):
    """bench --suite --native on the Cornell box and sphere-1m: rows sphere1m and sphere1m_first."""
    scenes = "cornell,sphere-1k" if r.quick else "cornell,sphere-1m"
    extra = ["--size", "32x32", "--spp", "1", "--runs", "1"] if r.quick else []
    share, native_share, first, build, rate = [], [], [], [], []
    for i in range(r.runs):
        d = r.json(["bench", "--suite", "--native", "--scenes", scenes] + extra, "suite_%d" % i)
        s = {x["name"]: x for x in d["scenes"]}
        big = s[scenes.split(",")[1]]
        share.append(big["share_of_cornell"])
        native_share.append(big["native"]["share_of_cornell"])
        first.append(big["first_frame"]["seconds"])
        build.append(big["bvh"]["build_seconds"])
        rate.append(big["bvh"]["triangles_per_second"])
    return {"command": "fragpath bench --suite --native --scenes " + scenes + (" " + " ".join(extra) if extra else ""),
            "share_of_cornell": share, "native_share_of_cornell": native_share, "first_frame_seconds": first,
            "bvh_build_seconds": build, "bvh_triangles_per_second": rate}


def measure_glb(r):
    extra = ["--size", "16x16", "--spp", "1"] if r.quick else []
    first, load = [], []
    for i in range(r.runs):
        d = r.json(["bench", "--suite", "--scenes", "sphere-1m-glb", "--runs", "1"] + extra, "glb_%d" % i)
        s = d["scenes"][0]
        first.append(s["first_frame"]["seconds"])
        load.append(s["first_frame"]["load_seconds"])
    return {"command": "fragpath bench --suite --scenes sphere-1m-glb --runs 1" + (" " + " ".join(extra) if extra else ""),
            "first_frame_seconds": first, "load_seconds": load}


def measure_instancing(r):
    grid = r.path("instanced_grid")
    n, rings = ("3", "10") if r.quick else ("10", "70")
    subprocess.run([sys.executable, os.path.join(ROOT, "tools/make_instanced_grid.py"), grid, n, rings], check=True,
                   stdout=subprocess.DEVNULL)
    scene = os.path.join(grid, "grid.gltf")
    args = ["bench", scene] + (["--size", "32x32", "--spp", "1", "--runs", "1"] if r.quick else
                               ["--size", "256x256", "--spp", "4", "--runs", "5"])
    result = {"command": "fragpath bench GRID/grid.gltf %s [--flatten-instances] (tools/make_instanced_grid.py GRID %s %s)"
                         % (" ".join(args[2:]), n, rings)}
    for kind, flag in (("instanced", []), ("flattened", ["--flatten-instances"])):
        result[kind] = {"paths_per_cpu_second": [], "gpu_bytes": [], "first_frame_seconds": []}
    for i in range(r.runs):   # alternating, so that a change of load hits both alike
        for kind, flag in (("instanced", []), ("flattened", ["--flatten-instances"])):
            d = r.json(args + flag, "instancing_%s_%d" % (kind, i))
            result[kind]["paths_per_cpu_second"].append(d["summary"]["paths_per_cpu_second"]["median"])
            result[kind]["gpu_bytes"].append(d["gpu"]["bytes"])
            result[kind]["first_frame_seconds"].append(d["first_frame"]["seconds"])
    return result


def measure_first_frame(r):
    """The Cornell box at 512x512: first frame with a cold and a warm shader cache, wall and CPU seconds
    (render --json's first_frame_seconds and first_frame.cpu_seconds)."""
    size = "64x64" if r.quick else "512x512"
    result = {"command": "fragpath render --size %s --spp 1 --json (MESA_SHADER_CACHE_DISABLE=true for cold)" % size}
    for kind, env in (("cold", {"MESA_SHADER_CACHE_DISABLE": "true"}), ("warm", {})):
        if kind == "warm":
            r.render(["--size", size, "--spp", "1"], "first_frame_fill")   # fills the cache
        wall, cpu = [], []
        for i in range(max(r.runs, 3) if not r.quick else 1):
            image = r.path("images", "first_frame.png")
            d = r.json(["render", "--size", size, "--spp", "1", "--quiet", "-o", image], "first_frame_%s_%d" % (kind, i),
                       env=env)
            wall.append(d["first_frame_seconds"])
            cpu.append(d["first_frame"]["cpu_seconds"])
        result[kind] = {"wall_seconds": wall, "cpu_seconds": cpu}
    return result


def measure_gltf_startup(r):
    samples = os.path.join(ROOT, "..", "shared", "gltf-samples")
    models = sample_models(samples) if os.path.isdir(samples) else []
    if r.quick:
        models = models[:2]
    big = []
    if not r.quick:
        big_dir = r.path("big_models")
        if not os.path.exists(os.path.join(big_dir, "helmet.glb")):
            subprocess.run([sys.executable, os.path.join(ROOT, "tools/make_big_gltf.py"), big_dir], check=True,
                           stdout=subprocess.DEVNULL)
        big = [os.path.join(big_dir, m) for m in ("helmet.glb", "lamp.glb")]
    result = {"command": "fragpath render MODEL --size 160x120 --spp 16 --json (warm shader cache)", "models": {}}
    for model in models + big:
        r.render([model, "--size", "160x120", "--spp", "1"], "startup_warm")   # warms the shader cache
        wall, cpu = [], []
        for i in range(r.runs):
            d, _ = r.render([model, "--size", "160x120", "--spp", "16"], "startup")
            wall.append(d["first_frame_seconds"])
            cpu.append(d["first_frame"]["cpu_seconds"])
        result["models"][os.path.basename(model)] = {"wall_seconds": wall, "cpu_seconds": cpu,
                                                     "generated": model in big}
    return result


def measure_sampler(r):
    """Paths per CPU-second of Sobol against independent numbers (bench, 512x512), and the error of the
    Cornell box at 32x32 (nee, depth 5) against a reference: Sobol at 64 spp, independent at 512, the
    mean squared error over 4 seeds each."""
    size = ["--size", "64x64", "--spp", "1", "--runs", "1"] if r.quick else []
    ratio = []
    for i in range(r.runs):
        sobol = r.json(["bench", "--sampler", "sobol"] + size, "sampler_sobol_%d" % i)
        indep = r.json(["bench", "--sampler", "independent"] + size, "sampler_independent_%d" % i)
        ratio.append(sobol["summary"]["paths_per_cpu_second"]["median"] /
                     indep["summary"]["paths_per_cpu_second"]["median"])
    ref_spp, low, high, seeds = (256, 4, 32, 2) if r.quick else (16384, 64, 512, 4)
    _, reference = r.render(["--size", "32x32", "--spp", ref_spp, "--seed", 1000], "sampler_reference")
    errors = {}
    for sampler, spp in (("sobol", low), ("independent", high)):
        mse = []
        for seed in range(1, seeds + 1):
            _, image = r.render(["--size", "32x32", "--spp", spp, "--seed", seed, "--sampler", sampler],
                                "sampler_%s_%d" % (sampler, seed))
            mse.append(rmse(image, reference) ** 2)
        errors[sampler] = {"spp": spp, "rmse": math.sqrt(statistics.mean(mse))}
    return {"command": "fragpath bench --sampler sobol|independent; fragpath render --size 32x32 --spp N --seed S "
                       "--sampler NAME against %d spp of seed 1000" % ref_spp,
            "paths_per_cpu_second_sobol_over_independent": ratio, "error": errors, "reference_spp": ref_spp}


def efficiency_pair(r, scene, size, spp, flag_name, choices, name):
    """Two seeds of each choice: the variance of one image (half the mean squared difference of the two
    seeds' images) and the render's CPU seconds. For an unbiased estimator the CPU time to a given error
    goes as variance x CPU seconds per sample, so their ratio is the ratio of the times to equal error."""
    result = {}
    for choice in choices:   # untimed: the shader cache then holds both programs, and no run pays the JIT
        r.render([scene, "--size", "16x16", "--spp", 1, flag_name, choice], "%s_%s_warm_up" % (name, choice))
    for choice in choices:
        images, cpu = [], []
        for seed in (1, 2):
            d, image = r.render([scene, "--size", size, "--spp", spp, "--seed", seed, flag_name, choice],
                                "%s_%s_%d" % (name, choice, seed))
            images.append(image)
            cpu.append(d["cpu_seconds"])
        result[choice] = {"variance": variance_of_mean(*images), "cpu_seconds": cpu}
    return result


def measure_choice_efficiency(r, scene_path, quick_size_spp, size_spp, flag, choices, tag):
    """Variance and CPU time of two values of `flag` on one scene, one pair per run."""
    scene = os.path.join(ROOT, scene_path)
    size, spp = quick_size_spp if r.quick else size_spp
    runs = [efficiency_pair(r, scene, size, spp, flag, choices, "%s_%d" % (tag, i)) for i in range(r.runs)]
    return {"command": "fragpath render %s --size %s --spp %d --seed 1|2 %s %s" %
                       (scene_path, size, spp, flag, "|".join(choices)), "runs": runs}


def measure_caustics(r):
    return measure_choice_efficiency(r, "assets/cornell_spheres/cornell_spheres.json", ("32x32", 4),
                                     ("128x128", 64), "--caustics", ("light", "path"), "caustics")


def measure_light_tree(r):
    return measure_choice_efficiency(r, "assets/many_lights/many_lights.json", ("32x32", 2), ("128x128", 16),
                                     "--light-selection", ("tree", "power"), "light_tree")


def measure_denoisers(r):
    """As the section "Denoisers: error against a converged render": the Cornell box, 64x64, seed 1,
    against 1024 spp of seed 99, without the lamp and a one-pixel ring around it."""
    ref_spp = 64 if r.quick else 1024
    _, reference = r.render(["--size", "64x64", "--spp", ref_spp, "--seed", 99], "denoise_reference")
    width = height = 64
    bright = [max(reference[3 * i:3 * i + 3]) > 2 for i in range(width * height)]
    mask = [True] * (width * height)
    for y in range(height):
        for x in range(width):
            for dy in (-1, 0, 1):
                for dx in (-1, 0, 1):
                    u, v = x + dx, y + dy
                    if 0 <= u < width and 0 <= v < height and bright[v * width + u]:
                        mask[y * width + x] = False
    result = {"command": "fragpath render --size 64x64 --spp N --seed 1 -o raw.pfm --denoise NAME --denoised-out "
                         "NAME.pfm, against %d spp of seed 99" % ref_spp, "masked_pixels": mask.count(False),
              "spp": {}}
    for spp in (1, 16, 64):
        row = {}
        for name in ("bilateral", "atrous"):
            out = r.path("images", "denoised_%s_%d.pfm" % (name, spp))
            _, raw = r.render(["--size", "64x64", "--spp", spp, "--seed", 1, "--denoise", name, "--denoised-out", out],
                              "denoise_raw_%s_%d" % (name, spp))
            row["raw"] = rmse(raw, reference, mask)
            row[name] = rmse(read_pfm(out), reference, mask)
        result["spp"][str(spp)] = row
    return result


def measure_caustic_study(r):
    args = ["bench", "--study", "caustic"] + (["--budget", "1", "--reference-spp", "64"] if r.quick else
                                              ["--budget", "20", "--reference-spp", "8192"])
    text = r.run(args)
    tables, roughness = {}, None
    for line in text.splitlines():
        m = re.match(r"glass roughness ([0-9.]+)", line)
        if m:
            roughness = m.group(1)
            tables[roughness] = {}
        m = re.match(r"\s+(nee\+light|nee|bdpt)\s+(\d+)\s+([0-9.]+)\s+([0-9.]+)\s+([0-9.e+-]+)\s+([0-9.e+-]+)\s+([0-9.e+-]+)",
                     line)
        if m and roughness is not None:
            tables[roughness][m.group(1)] = {"spp": int(m.group(2)), "cpu_seconds": float(m.group(3)),
                                             "variance_under_sphere": float(m.group(7))}
    return {"command": "fragpath " + " ".join(args), "tables": tables}


def measure_viewer(r):
    frames = "10" if r.quick else "300"
    xvfb = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"]
    frame_ms, paths = [], []
    for i in range(r.runs):
        text = r.run(["view", "--frames", frames], prefix=xvfb)
        m = re.search(r"median frame time ([0-9.]+) ms; ([0-9.e+]+) samples/s, ([0-9.e+]+) paths/s", text)
        frame_ms.append(float(m.group(1)))
        paths.append(float(m.group(3)))
    bench = []
    for i in range(r.runs):
        d = r.json(["bench", "--size", "800x600", "--spp", "1" if r.quick else "4", "--runs", "1" if r.quick else "3"],
                   "viewer_bench_%d" % i)
        bench.append(d["summary"]["paths_per_second"]["median"])
    return {"command": "xvfb-run fragpath view --frames %s; fragpath bench --size 800x600 --spp 4 --runs 3" % frames,
            "median_frame_ms": frame_ms, "paths_per_second": paths, "bench_paths_per_second": bench}


def frames_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def measure_realtime(r):
    size, frames, ref_spp = ("32x32", 6, 8) if r.quick else ("128x128", 40, 512)
    cache = r.path("realtime_refs_%s_%d" % (size, ref_spp), "x")[:-2]
    base = ["realtime", "--size", size, "--frames", frames, "--reference-spp", ref_spp, "--reference-cache", cache]
    variants = {"reuse_2spp": ["--spp", 2], "atrous_alone_1spp": ["--spp", 1, "--temporal", "off"],
                "brute_force_2spp": ["--spp", 2, "--temporal", "off", "--filter", "none"]}
    result = {"command": "fragpath realtime --size %s --frames %d --reference-spp %d --reference-cache DIR "
                         "[--spp 2 | --spp 1 --temporal off | --spp 2 --temporal off --filter none]"
                         % (size, frames, ref_spp), "runs": {k: {"ms": [], "cpu_ms": None, "flip": []} for k in variants}}
    for i in range(r.runs):
        for name, extra in variants.items():
            out = r.path("realtime", name, "x")[:-2]
            r.run(base + extra + ["--out", out])
            rows = frames_csv(os.path.join(out, "frames.csv"))
            result["runs"][name]["ms"].append(med([float(x["ms"]) for x in rows]))
            result["runs"][name]["flip"].append(statistics.mean(float(x["flip"]) for x in rows))
    # The pipeline's share of a 1-spp frame at 256x256 once most histories hold 16 samples (frames 16-29).
    share_size, share_frames, first = ("64x64", 8, 4) if r.quick else ("256x256", 30, 16)
    shares, parts = [], []
    for i in range(r.runs):
        out = r.path("realtime", "share", "x")[:-2]
        r.run(["realtime", "--size", share_size, "--frames", share_frames, "--spp", 1, "--out", out])
        rows = frames_csv(os.path.join(out, "frames.csv"))[first:]
        trace = med([float(x["trace_ms"]) for x in rows])
        temporal = med([float(x["temporal_ms"]) for x in rows])
        filt = med([float(x["filter_ms"]) for x in rows])
        shares.append((temporal + filt) / (trace + temporal + filt))
        parts.append([trace, temporal, filt])
    result["share"] = {"command": "fragpath realtime --size %s --frames %d --spp 1, frames %d on"
                                  % (share_size, share_frames, first), "reprojection_and_filter_share": shares,
                       "trace_temporal_filter_ms": parts}
    return result


def measure_study(r):
    out = r.path("study", "x")[:-2]
    args = ["study", "--scenes", "cornell", "--integrators", "nee", "--denoisers", "none", "--practice-frames", "0",
            "--no-plots", "--quiet", "--out", out]
    if r.quick:
        args += ["--size", "16x16", "--max-spp", "4", "--reference-spp", "16"]
    else:
        args += ["--runs", str(r.runs), "--reference", os.path.join(ROOT, "docs/study/reference_cornell.exr")]
    r.run(args)
    with open(os.path.join(out, "report.md")) as f:
        report = f.read()
    m = re.search(r"^\| nee \| none \| [^|]* \| ([0-9.]+) \| ([0-9.e+]+) \| ([0-9.]+)%", report, re.M)
    if not m:
        raise RuntimeError("report.md has no row for nee without a denoiser")
    return {"command": "fragpath " + " ".join(a for a in args if a != out).replace("--out", "--out DIR"),
            "flops_per_path": float(m.group(1)), "paths_per_cpu_second": float(m.group(2)),
            "efficiency_percent": float(m.group(3))}


MEASURE = {"cornell": measure_cornell, "suite": measure_suite, "glb": measure_glb, "instancing": measure_instancing,
           "first_frame": measure_first_frame, "gltf_startup": measure_gltf_startup, "sampler": measure_sampler,
           "caustics": measure_caustics, "light_tree": measure_light_tree, "denoisers": measure_denoisers,
           "caustic_study": measure_caustic_study, "viewer": measure_viewer, "realtime": measure_realtime,
           "study": measure_study}


# ----------------------------------------------------------------------------------------------------------
# The table: rows from the measurements. Everything below reads only the results dict, so that it can be
# tested on a fixture and rerun with --from-json.


def mega(values):
    return span([v / 1e6 for v in values], "%.3f") + " M"


def ratio_span(values, fmt="%.2f"):
    return span(values, fmt)


def row_cornell(m):
    return ("Cornell box, 512x512, nee, depth 5: shader paths per CPU-second",
            "%s; %s times a single-threaded native C++ tracer of the same algorithm on the same tree" %
            (mega(m["shader_paths_per_cpu_second"]), ratio_span(m["gpu_over_native"], "%.3f")))


def row_sphere1m(m):
    return ("sphere-1m (a million triangles): paths per CPU-second as a share of the Cornell box's",
            "%s %% (the native reference: %s %%)" % (span([100 * v for v in m["share_of_cornell"]], "%.1f"),
                                                   span([100 * v for v in m["native_share_of_cornell"]], "%.1f")))


def row_sphere1m_first(m):
    rate = med(m["bvh_triangles_per_second"]) / 1e6
    return ("sphere-1m: first frame (256x256, warm shader cache) and BVH build (both cores)",
            "%s s; build %s s, %.1f M triangles/s (medians)" % (span(m["first_frame_seconds"], "%.2f"),
                                                               span(m["bvh_build_seconds"], "%.3f"), rate))


def row_glb(m):
    return ("sphere-1m as a `.glb` file: first frame (256x256), load stage",
            "%s s wall; load %s s" % (span(m["first_frame_seconds"], "%.2f"), span(m["load_seconds"], "%.2f")))


def row_instancing(m):
    i, f = m["instanced"], m["flattened"]
    return ("instancing: 100 instances of a 19,320-triangle sphere against the same scene flattened",
            "%.2fx the paths per CPU-second, 1/%.0f of the GPU memory (%.1f against %.1f MB), first frame %.2f "
            "against %.2f s" % (med(i["paths_per_cpu_second"]) / med(f["paths_per_cpu_second"]),
                                med(f["gpu_bytes"]) / med(i["gpu_bytes"]), med(i["gpu_bytes"]) / 1e6,
                                med(f["gpu_bytes"]) / 1e6, med(i["first_frame_seconds"]),
                                med(f["first_frame_seconds"])))


def row_first_frame(m):
    c, w = m["cold"], m["warm"]
    return ("Cornell box, 512x512: first frame, cold and warm shader cache",
            "%s s and %s s wall; %s and %s CPU-s" % (span(c["wall_seconds"], "%.3f"), span(w["wall_seconds"], "%.3f"),
                                                    span(c["cpu_seconds"], "%.3f"), span(w["cpu_seconds"], "%.3f")))


def row_gltf_startup(m):
    shared = {k: v for k, v in m["models"].items() if not v["generated"]}
    big = {k: v for k, v in m["models"].items() if v["generated"]}
    parts = []
    if shared:
        walls = [med(v["wall_seconds"]) for v in shared.values()]
        cpus = [med(v["cpu_seconds"]) for v in shared.values()]
        parts.append("every shared Khronos sample (%d) %.2f-%.2f s, %.2f-%.2f CPU-s" %
                     (len(shared), min(walls), max(walls), min(cpus), max(cpus)))
    for name, v in sorted(big.items()):
        parts.append("%s %.2f s, %.2f CPU-s" % (name, med(v["wall_seconds"]), med(v["cpu_seconds"])))
    return ("glTF models as users bring them, 160x120: first frame (warm shader cache)", "; ".join(parts))


def row_sampler(m):
    e = m["error"]
    return ("the default Sobol sampler against independent numbers",
            "RMSE %.4f at %d spp against independent numbers' %.4f at %d (Cornell box, 32x32); %s of their paths "
            "per CPU-second at 512x512" % (e["sobol"]["rmse"], e["sobol"]["spp"], e["independent"]["rmse"],
                                           e["independent"]["spp"],
                                           ratio_span(m["paths_per_cpu_second_sobol_over_independent"])))


def pair_ratios(m, a, b):
    """Per run: variance a / b, CPU a / b, and their product (the time to equal error, a over b)."""
    variance, cpu, time_ratio = [], [], []
    for run in m["runs"]:
        v = run[a]["variance"] / run[b]["variance"]
        c = statistics.mean(run[a]["cpu_seconds"]) / statistics.mean(run[b]["cpu_seconds"])
        variance.append(v)
        cpu.append(c)
        time_ratio.append(v * c)
    return variance, cpu, time_ratio


def row_caustics(m):
    v, c, t = pair_ratios(m, "light", "path")
    return ("nee's light pass for caustics, glass and gold spheres, 128x128, 64 spp",
            "%sx the variance for %sx the CPU time of camera paths alone: the same error in %sx the time" %
            (ratio_span(v), ratio_span(c), ratio_span(t)))


def row_light_tree(m):
    v, c, t = pair_ratios(m, "tree", "power")
    return ("the light tree against the choice by power, 112 lamps (128x128, 16 spp)",
            "the same error in %sx the CPU time (%sx the variance, %sx the CPU time per sample)" %
            (ratio_span(t), ratio_span(v), ratio_span(c)))


def row_denoisers(m):
    s = m["spp"]
    at = ", ".join("%.2f at %s" % (s[k]["atrous"] / s[k]["raw"], k) for k in ("1", "16", "64"))
    bi = ", ".join("%.2f at %s" % (s[k]["bilateral"] / s[k]["raw"], k) for k in ("1", "16", "64"))
    return ("denoisers: RMSE against the raw image's, away from the lamp (Cornell box, 64x64)",
            "à-trous %s spp; bilateral %s spp" % (at, bi))


def row_caustic_study(m):
    smooth = m["tables"].get("0.0", {})
    per_cpu = {k: v["variance_under_sphere"] for k, v in smooth.items()}
    return ("bdpt and nee's light pass against nee's camera paths alone on a glass caustic, at equal CPU time",
            "variance under the smooth sphere %.0f times lower with bdpt, %.0f times with nee's light pass" %
            (per_cpu["nee"] / per_cpu["bdpt"], per_cpu["nee"] / per_cpu["nee+light"]))


def row_viewer(m):
    share = [p / med(m["bench_paths_per_second"]) for p in m["paths_per_second"]]
    return ("viewer, 800x600 window with its panel (under Xvfb)",
            "median frame %s ms; %s %% of the offscreen renderer's paths per wall second" %
            (span(m["median_frame_ms"], "%.1f"), span([100 * s for s in share], "%.0f")))


def row_realtime(m):
    runs = m["runs"]
    a2, b, c2 = (med(runs[k]["flip"]) for k in ("reuse_2spp", "atrous_alone_1spp", "brute_force_2spp"))
    ms = lambda k: span(runs[k]["ms"], "%.0f")
    share = m["share"]
    return ("real time, Cornell orbit 128x128: mean FLIP with reuse + à-trous (2 spp a frame) against the filter "
            "alone (1 spp) and brute force (2 spp)",
            "**%.2f** of à-trous alone (FLIP %.3f against %.3f; %s against %s ms a frame), %.2f of brute force; "
            "reprojection + filter **%s %%** of a 1-spp frame at 256x256 once histories pass 16 samples" %
            (a2 / b, a2, b, ms("reuse_2spp"), ms("atrous_alone_1spp"), a2 / c2,
             span([100 * s for s in share["reprojection_and_filter_share"]], "%.0f")))


def row_study(m):
    return ("the study's efficiency: FLOPs per path x paths per CPU-second against the CPU's peak (Cornell box, "
            "nee, 128x128)",
            "%.2f %% of peak (%.0f FLOPs per path, %.0f k paths per CPU-s)" %
            (m["efficiency_percent"], m["flops_per_path"], m["paths_per_cpu_second"] / 1e3))


ROWS = {"cornell": ("cornell", row_cornell), "sphere1m": ("suite", row_sphere1m),
        "sphere1m_first": ("suite", row_sphere1m_first), "glb": ("glb", row_glb),
        "instancing": ("instancing", row_instancing), "first_frame": ("first_frame", row_first_frame),
        "gltf_startup": ("gltf_startup", row_gltf_startup), "sampler": ("sampler", row_sampler),
        "caustics": ("caustics", row_caustics), "light_tree": ("light_tree", row_light_tree),
        "denoisers": ("denoisers", row_denoisers), "caustic_study": ("caustic_study", row_caustic_study),
        "viewer": ("viewer", row_viewer), "realtime": ("realtime", row_realtime), "study": ("study", row_study)}

RECORDED_WHAT = {
    "race": "against Blender's Cycles, fragpath's default command, 256x256, depth 64: CPU time to reach Cycles' "
            "error (16, 64 and 256 spp)",
    "bvh_quality": "BVH quality: binned SAH against the full sweep",
}


def race_row(race):
    """The race row from tools/race_cycles.py's --json: per scene, fragpath's CPU time for Cycles' error over
    Cycles', against Cycles' reference, at each sample count."""
    cells = []
    for entry in race["races"]:
        ratios = [x["ratio"] for x in entry["crossings"] if x["renderer"] == "fragpath" and x["reference"] ==
                  sorted(entry["references"])[0]]
        cells.append("%s %s" % (entry["scene"], " / ".join("%.2fx" % v for v in ratios)))
    return "; ".join(cells)


def table(results):
    """The lines between the markers: the stamp, then the table."""
    stamp = results["stamp"]
    lines = [
        "Written by `tools/benchmarks.sh`%s from one run at `%s` on %s: %s, %d cores, %s, `LP_NUM_THREADS=%s`; "
        "load average %.1f at the start and %.1f at the end%s. Each figure is the median of %d invocations "
        "(min-max beside it); rows read from another source say which, with its commit and date." %
        (" --quick (toy sizes: the figures mean nothing)" if stamp["quick"] else "", stamp["commit"],
         stamp["date"], stamp["cpu"], stamp["cores"], stamp["mesa"], stamp["lp_num_threads"], stamp["load_start"],
         stamp["load_end"], " (other work shared the machine: prefer the CPU-time figures)"
         # The run's own LP_NUM_THREADS=2 raises the load to about 2 by its end: only the start tells.
         if stamp["load_start"] > 1.0 else "", stamp["runs"]),
        "",
        "| what | figure | section |",
        "|---|---|---|",
    ]
    for key in ORDER:
        if key in RECORDED:
            rec = dict(RECORDED[key])
            if key == "race" and "race" in results.get("read", {}):
                race = results["read"]["race"]
                rec = {"figure": race_row(race), "source": "tools/race_cycles.py --json", "commit": race["commit"],
                       "date": race["date"]}
            lines.append("| %s | %s (from %s, `%s`, %s) | %s |" % (RECORDED_WHAT[key], rec["figure"], rec["source"],
                                                                   rec["commit"], rec["date"], SECTIONS[key]))
            continue
        source, make = ROWS[key]
        measured = results["measured"].get(source)
        if measured is None:
            continue
        if "failed" in measured:
            lines.append("| %s | not measured in this run: %s | %s |" % (key, measured["failed"].splitlines()[0],
                                                                        SECTIONS[key]))
            continue
        what, figure = make(measured)
        lines.append("| %s | %s | %s |" % (what, figure, SECTIONS[key]))
    return lines


def rewrite(path, lines):
    with open(path) as f:
        text = f.read()
    if BEGIN not in text or END not in text:
        raise SystemExit("%s has no %s ... %s markers" % (path, BEGIN, END))
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    new = head + BEGIN + "\n" + "\n".join(lines) + "\n" + END + tail
    with open(path + ".tmp", "w") as f:
        f.write(new)
    os.replace(path + ".tmp", path)


# ----------------------------------------------------------------------------------------------------------


def machine_stamp(fragpath, quick, runs):
    def git(*args):
        return subprocess.run(["git", "-C", ROOT] + list(args), capture_output=True, text=True).stdout.strip()
    commit = git("rev-parse", "--short", "HEAD")
    if git("status", "--porcelain", "--untracked-files=no", "--", "src", "glsl"):
        commit += " with uncommitted changes to src/ or glsl/"
    cpu = "unknown CPU"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    version = subprocess.run([fragpath, "--version"], capture_output=True, text=True).stdout
    mesa = re.search(r"(Mesa [0-9][^\s]*)", version)
    llvm = re.search(r"(LLVM [0-9.]+)", version)
    return {"commit": commit, "date": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"), "cpu": cpu,
            "cores": os.cpu_count(), "mesa": "llvmpipe (%s), %s" % (llvm.group(1) if llvm else "?",
                                                                      mesa.group(1) if mesa else "no Mesa"),
            "lp_num_threads": os.environ.get("LP_NUM_THREADS", "unset"), "load_start": os.getloadavg()[0],
            "quick": quick, "runs": runs}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--fragpath", default=os.path.join(ROOT, "build/fragpath"))
    parser.add_argument("--runs", type=int, default=None, help="invocations per figure (default 3; 1 with --quick)")
    parser.add_argument("--quick", action="store_true", help="toy sizes: checks that the script works")
    parser.add_argument("--only", default="", help="measure only these (comma-separated: %s)" % ",".join(MEASURE))
    parser.add_argument("--work", default=os.path.join(ROOT, "build/benchmarks"), help="scratch files")
    parser.add_argument("--json", default=None, help="write the measurements here (default WORK/at_a_glance.json)")
    parser.add_argument("--from-json", default=None, help="write the table from this file; measure nothing")
    parser.add_argument("--race-json", default=None, help="tools/race_cycles.py --suite --json output for the race row")
    parser.add_argument("--benchmarks", default=os.path.join(ROOT, "BENCHMARKS.md"))
    parser.add_argument("--no-write", action="store_true", help="print the table instead of rewriting BENCHMARKS.md")
    parser.add_argument("--write-quick", action="store_true", help="rewrite BENCHMARKS.md even with --quick")
    args = parser.parse_args()

    if args.from_json:
        with open(args.from_json) as f:
            results = json.load(f)
    else:
        if "LP_NUM_THREADS" not in os.environ:
            os.environ["LP_NUM_THREADS"] = "2"
        runs = args.runs or (1 if args.quick else 3)
        work = os.path.join(args.work, "quick" if args.quick else "full")
        os.makedirs(work, exist_ok=True)
        log = lambda s: print(s, file=sys.stderr, flush=True)
        runner = Runner(args.fragpath, work, args.quick, runs, log)
        results = {"stamp": machine_stamp(args.fragpath, args.quick, runs), "measured": {}, "read": {}}
        only = [x for x in args.only.split(",") if x] or list(MEASURE)
        for name in only:
            log("%s:" % name)
            started = time.process_time(), time.time()
            try:
                results["measured"][name] = MEASURE[name](runner)
            except Exception as e:   # one failed row must not lose the others
                results["measured"][name] = {"failed": "%s: %s" % (type(e).__name__, e)}
                log("  failed: %s" % e)
            log("  %s done in %.0f s" % (name, time.time() - started[1]))
        results["stamp"]["load_end"] = os.getloadavg()[0]
        if args.race_json:
            with open(args.race_json) as f:
                results["read"]["race"] = json.load(f)
        out = args.json or os.path.join(work, "at_a_glance.json")
        with open(out, "w") as f:
            json.dump(results, f, indent=1)
        log("measurements: %s" % out)

    lines = table(results)
    if args.no_write or (args.only and not args.from_json) or (results["stamp"]["quick"] and not args.write_quick):
        print("\n".join(lines))
    else:
        rewrite(args.benchmarks, lines)
        print("rewrote the at-a-glance table of %s" % args.benchmarks)


if __name__ == "__main__":
    main()
