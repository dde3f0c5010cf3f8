#!/usr/bin/env python3
# The race against Cycles with no reference at all: each renderer's noise alone, from a finished race.
#
# tools/race_cycles.py measures error against a converged reference, which charges each renderer the
# reference's bias as well as its own noise: against Cycles' reference fragpath pays Cycles' 0.2 % offset
# on lamp-lit rooms (`--analytic`), against fragpath's Cycles pays it. Here the error is the noise alone,
# estimated from the race's own runs (each a different seed): per pixel and channel the unbiased variance
# of the --runs renders of one sample count, averaged over the image, is the mean squared error a render
# of that count has around its own renderer's converged image. Neither renderer's bias enters, nor the
# reference's noise. Times are the race's (the median CPU time less set-up). Reads the --json file and the
# renders that tools/race_cycles.py --out kept; prints, per race, each renderer's noise RMSE per sample
# count and the CPU time each needs for the other's noise, and the two renderers' mean ratio at the
# largest count (how far apart their converged images are).
#
#   tools/race_noise.py race.json [--out build/race]
import argparse
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from race_cycles import read_pfm, time_for_error  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def noise_mse(images):
    """Mean over pixels and channels of the unbiased variance across `images` (two or more)."""
    n = len(images)
    total = 0.0
    for values in zip(*images):
        mean = sum(values) / n
        total += sum((v - mean) ** 2 for v in values) / (n - 1)
    return total / len(images[0])


def main():
    parser = argparse.ArgumentParser(description="noise alone, from a finished race's runs")
    parser.add_argument("race_json")
    parser.add_argument("--out", default=os.path.join(ROOT, "build/race"), help="the race's --out folder")
    args = parser.parse_args()
    import json
    document = json.load(open(args.race_json))
    for race in document["races"]:
        label = "%s_d%d" % (race["scene"], race["max_depth"])
        runs = race["runs"]
        if runs < 2:
            sys.exit("%s: %d run; the noise needs 2 or more" % (label, runs))
        print("== %s, %dx%d, depth %d, %d runs (commit %s, %s)" % (race["scene"], race["size"], race["size"],
                                                                race["max_depth"], runs, document["commit"],
                                                                document["date"]))
        curves, means = {}, {}
        for renderer in ("fragpath", "cycles"):
            curves[renderer] = []
            for spp in race["spp"]:
                images = [read_pfm(os.path.join(args.out, "%s_%s_%d_%d.pfm" % (label, renderer, spp, run)))
                          for run in range(runs)]
                noise = math.sqrt(noise_mse(images))
                seconds = race["summary"][renderer]["spp"][str(spp)]["cpu_s_less_setup"]
                curves[renderer].append((max(seconds, 1e-3), noise))
                means[renderer] = statistics.mean(sum(image) / len(image) for image in images)
                print("%-9s %6d spp  %8.2f CPU s  noise RMSE %.5f" % (renderer, spp, seconds, noise))
        for a, b in (("fragpath", "cycles"), ("cycles", "fragpath")):
            for (t, e), spp in zip(curves[b], race["spp"]):
                ta = time_for_error(curves[a], e)
                print("%s needs %.2f CPU s for %s's noise %.5f at %d spp (%s: %.2f s): %.2fx" %
                      (a, ta, b, e, spp, b, t, ta / t))
        print("fragpath's mean over Cycles' at %d spp: %.4f" % (race["spp"][-1], means["fragpath"] / means["cycles"]))


if __name__ == "__main__":
    main()
