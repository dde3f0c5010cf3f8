#!/usr/bin/env python3
"""Time to first frame of glTF/OBJ models, as BENCHMARKS.md's "Start-up on real models" lists it: each
model rendered RUNS times with `fragpath render MODEL --size 160x120 --spp 16 --json`, and the median,
min and max of its first_frame_seconds, with the median process CPU time to the first frame and the
median of each stage (first_frame in the JSON; a binary older than those fields prints only the times).

    LP_NUM_THREADS=2 python3 tools/startup_times.py [--fragpath build/fragpath] [--runs 3]
        [--samples ../shared/gltf-samples] [--timeout 900] [MODEL ...]

Without MODEL arguments, every .gltf and .glb under --samples (not its screenshot folders). Prints one
markdown table row per model."""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

STAGES = ["load_seconds", "context_seconds", "bvh_seconds", "pack_and_upload_seconds", "compile_seconds",
          "first_pass_seconds"]


def sample_models(root):
    found = []
    for directory, _, files in os.walk(root):
        for name in files:
            if name.endswith((".gltf", ".glb")) and "screenshot" not in directory:
                found.append(os.path.join(directory, name))
    return sorted(found)


def time_model(fragpath, model, runs, timeout, work):
    results = []
    for run in range(runs):
        stats = os.path.join(work, "stats.json")
        if os.path.exists(stats):
            os.remove(stats)
        command = [fragpath, "render", model, "--size", "160x120", "--spp", "16", "--json", stats, "--quiet",
                   "-o", os.path.join(work, "out.png")]
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"error": "over %d s" % timeout}
        if done.returncode != 0:
            return {"error": done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "failed"}
        with open(stats) as f:
            results.append(json.load(f))
    first = [r["first_frame_seconds"] for r in results]
    row = {"triangles": results[0]["triangles"],
           "texture_mb": results[0]["memory"]["gpu_texture_bytes"] / 1e6,
           "median": statistics.median(first), "min": min(first), "max": max(first)}
    if "first_frame" in results[0]:
        row["cpu"] = statistics.median(r["first_frame"]["cpu_seconds"] for r in results)
        row["stages"] = {s: statistics.median(r["first_frame"][s] for r in results) for s in STAGES}
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("models", nargs="*")
    parser.add_argument("--fragpath", default="build/fragpath")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--samples", default="../shared/gltf-samples")
    parser.add_argument("--timeout", type=int, default=900)
    args = parser.parse_args()
    if "LP_NUM_THREADS" not in os.environ:
        print("warning: LP_NUM_THREADS is not set", file=sys.stderr)
    models = args.models or sample_models(args.samples)
    print("| model | triangles | texture MB | first frame s, median (min-max) | CPU-s | load, bvh, pack + upload, "
          "compile, first pass (s) |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for model in models:
            row = time_model(args.fragpath, model, args.runs, args.timeout, work)
            parts = model.split(os.sep)
            name = "%s (%s)" % (parts[-3], parts[-2]) if len(parts) >= 3 and not args.models else parts[-1]
            if "error" in row:
                print("%s: %s" % (name, row["error"]), file=sys.stderr)
                print("| %s | | | not rendered (stderr says why) | | |" % name, flush=True)
                continue
            cpu = "%.3f" % row["cpu"] if "cpu" in row else ""
            stages = ""
            if "stages" in row:
                s = row["stages"]
                stages = ", ".join("%.3f" % s[k] for k in ["load_seconds", "bvh_seconds", "pack_and_upload_seconds",
                                                           "compile_seconds", "first_pass_seconds"])
            print("| %s | %d | %.1f | %.3f (%.3f-%.3f) | %s | %s |" % (
                name, row["triangles"], row["texture_mb"], row["median"], row["min"], row["max"], cpu, stages),
                flush=True)


if __name__ == "__main__":
    main()
