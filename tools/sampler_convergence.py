#!/usr/bin/env python3
# RMSE against a long render as the sample count grows, for each sampler (BENCHMARKS.md, "Samplers"):
# independent numbers fall as N^-1/2; stratified ones should fall faster where the integrand has edges
# (the lamp's outline, shadow boundaries). Prints RMSE per sample count and the log-log slope from the
# first to the last count, per sampler. The reference's own mean squared error (estimated from two
# halves) is subtracted.
#
#   LP_NUM_THREADS=2 tools/sampler_convergence.py [--fragpath build/fragpath] [--scene FILE] [--size 32]
#                                                 [--reference-spp 65536] [--spp 64,128,256,512,1024]
#                                                 [--max-depth D] [--samplers independent,sobol]
# FRAGPATH_SAMPLERS: extra "name=binary" pairs (comma-separated) to compare another build's sobol.
import argparse
import json
import math
import os
import subprocess
import tempfile

from bias_check import ROOT, read_pfm


def main():
    parser = argparse.ArgumentParser(description="RMSE against sample count, per sampler")
    parser.add_argument("--fragpath", default=os.path.join(ROOT, "build/fragpath"))
    parser.add_argument("--scene", default=None, help="default: the built-in Cornell box")
    parser.add_argument("--size", type=int, default=32)
    parser.add_argument("--reference-spp", type=int, default=65536)
    parser.add_argument("--spp", default="64,128,256,512,1024")
    parser.add_argument("--seeds", type=int, default=2, help="renders averaged per point")
    parser.add_argument("--lamp-threshold", type=float, default=2.0,
                        help="the 'away' figure leaves out pixels with a 3x3 neighbour brighter than this")
    parser.add_argument("--reference-cache", default=None,
                        help="a JSON file: the reference's two halves, rendered once and reused")
    parser.add_argument("--max-depth", type=int, default=None, help="default: the scene's")
    parser.add_argument("--samplers", default="independent,sobol",
                        help="comma-separated; NAME=BINARY renders sobol with another build")
    args = parser.parse_args()
    out = tempfile.mkdtemp(prefix="sampler_convergence_")
    sizes = [args.size, args.size]

    def render(sampler, spp, seed, offset=0):
        binary = args.fragpath
        label = sampler.split("=", 1)[0]
        if "=" in sampler:
            binary, sampler = sampler.split("=", 1)[1], "sobol"
        path = os.path.join(out, "%s_%d_%d_%d.pfm" % (label, spp, seed, offset))
        depth = ["--max-depth", str(args.max_depth)] if args.max_depth is not None else []
        command = [binary, "render"] + depth + ([args.scene] if args.scene else []) + [
            "--size", "%dx%d" % (args.size, args.size), "--spp", str(spp), "--sampler", sampler,
            "--seed", str(seed), "--sample-offset", str(offset), "--samples-per-pass", "16", "--quiet",
            "-o", path]
        subprocess.run(command, check=True)
        width, height, image = read_pfm(path)
        sizes[:] = [width, height]
        return image

    # The reference: two independent halves (Sobol with different seeds: independent randomisations), so
    # that its own error can be estimated.
    half = args.reference_spp // 2
    cache = args.reference_cache
    if cache and os.path.exists(cache):
        with open(cache) as f:
            a, b = json.load(f)
    else:
        a, b = render("sobol", half, 1000), render("sobol", half, 1001)
        if cache:
            with open(cache, "w") as f:
                json.dump([a, b], f)
    reference = [(x + y) / 2 for x, y in zip(a, b)]
    # Var(mean of halves) = E[(a - b)^2] / 4 per pixel.
    reference_mse = sum((x - y) ** 2 for x, y in zip(a, b)) / len(a) / 4.0
    print("reference: %d spp (sobol), its own RMSE about %.5f" % (args.reference_spp, math.sqrt(reference_mse)))
    counts = [int(c) for c in args.spp.split(",")]
    # Away from the lamp: a 32x32 Cornell box's error sits in the few pixels on the lamp's edge, whose
    # pixel jitter (one 2D pair, stratified) converges fastest; the rest of the image is what a
    # large render is made of.
    width, height = sizes
    away = [i for i in range(width * height)
            if all(reference[min(max(i // width + dy, 0), height - 1) * width + min(max(i % width + dx, 0), width - 1)]
                   < args.lamp_threshold for dy in (-1, 0, 1) for dx in (-1, 0, 1))]
    away_reference_mse = sum((a[i] - b[i]) ** 2 for i in away) / len(away) / 4.0
    print("away from the lamp: %d of %d pixels" % (len(away), width * height))
    for sampler in args.samplers.split(","):
        rmse, away_rmse = [], []
        for spp in counts:
            mse = away_mse = 0.0
            for seed in range(1, args.seeds + 1):
                image = render(sampler, spp, seed)
                mse += sum((x - r) ** 2 for x, r in zip(image, reference)) / len(image) / args.seeds
                away_mse += sum((image[i] - reference[i]) ** 2 for i in away) / len(away) / args.seeds
            rmse.append(math.sqrt(max(mse - reference_mse, 1e-12)))
            away_rmse.append(math.sqrt(max(away_mse - away_reference_mse, 1e-12)))
        slope = math.log(rmse[-1] / rmse[0]) / math.log(counts[-1] / counts[0])
        away_slope = math.log(away_rmse[-1] / away_rmse[0]) / math.log(counts[-1] / counts[0])
        print("%-12s %s   slope %.3f   (away from the lamp)" % (
            sampler.split("=", 1)[0], "  ".join("%d spp %.5f" % (c, e) for c, e in zip(counts, away_rmse)),
            away_slope))
        print("%-12s %s   slope %.3f" % (sampler.split("=", 1)[0], "  ".join("%d spp %.5f" % (c, e) for c, e in zip(counts, rmse)), slope))


if __name__ == "__main__":
    main()
