#!/usr/bin/env python3
# RMSE against a long render as the sample count grows, for each sampler (BENCHMARKS.md, "Samplers"):
# independent numbers fall as N^-1/2; stratified ones should fall faster where the integrand has edges
# (the lamp's outline, shadow boundaries). Prints RMSE per sample count and the log-log slope from the
# first to the last count, per sampler. The reference's own mean squared error (estimated from two
# halves) is subtracted.
#
#   LP_NUM_THREADS=2 tools/sampler_convergence.py [--fragpath build/fragpath] [--scene FILE] [--size 32]
#                                                 [--reference-spp 65536] [--spp 64,128,256,512,1024]
import argparse
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
    args = parser.parse_args()
    out = tempfile.mkdtemp(prefix="sampler_convergence_")

    def render(sampler, spp, seed, offset=0):
        path = os.path.join(out, "%s_%d_%d_%d.pfm" % (sampler, spp, seed, offset))
        command = [args.fragpath, "render"] + ([args.scene] if args.scene else []) + [
            "--size", "%dx%d" % (args.size, args.size), "--spp", str(spp), "--sampler", sampler,
            "--seed", str(seed), "--sample-offset", str(offset), "--samples-per-pass", "16", "--quiet",
            "-o", path]
        subprocess.run(command, check=True)
        return read_pfm(path)[2]

    # The reference: two independent halves (Sobol with different seeds: independent randomisations), so
    # that its own error can be estimated.
    half = args.reference_spp // 2
    a, b = render("sobol", half, 1000), render("sobol", half, 1001)
    reference = [(x + y) / 2 for x, y in zip(a, b)]
    # Var(mean of halves) = E[(a - b)^2] / 4 per pixel.
    reference_mse = sum((x - y) ** 2 for x, y in zip(a, b)) / len(a) / 4.0
    print("reference: %d spp (sobol), its own RMSE about %.5f" % (args.reference_spp, math.sqrt(reference_mse)))
    counts = [int(c) for c in args.spp.split(",")]
    for sampler in ("independent", "sobol"):
        rmse = []
        for spp in counts:
            mse = 0.0
            for seed in range(1, args.seeds + 1):
                image = render(sampler, spp, seed)
                mse += sum((x - r) ** 2 for x, r in zip(image, reference)) / len(image) / args.seeds
            rmse.append(math.sqrt(max(mse - reference_mse, 1e-12)))
        slope = math.log(rmse[-1] / rmse[0]) / math.log(counts[-1] / counts[0])
        print("%-12s %s   slope %.3f" % (sampler, "  ".join("%d spp %.5f" % (c, e) for c, e in zip(counts, rmse)), slope))


if __name__ == "__main__":
    main()
