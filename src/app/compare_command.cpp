// `fragpath compare`: one error figure between a test image and its reference, by FLIP (image/flip.h)
// or the study's metrics, and optionally FLIP's error map as a picture.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/error.h"
#include "core/text.h"
#include "image/error_color_map.h"
#include "image/error_metrics.h"
#include "image/file_io.h"
#include "image/flip.h"
#include "image/image.h"
#include "image/image_stats.h"
#include "image/png.h"
#include "request/args.h"

namespace fp {

namespace {

const std::vector<std::string> kMetrics = {"flip", "hdr-flip", "rmse", "relmse", "ssim"};

std::vector<OptionGroup> compareOptions() {
    return {
        {"Comparison",
         {{"--metric", "", "NAME",
           "flip (LDR-FLIP), hdr-flip (HDR-FLIP), rmse, relmse or ssim (default: flip when both\n"
           "images are .png, hdr-flip otherwise)"},
          {"--ppd", "", "X",
           "FLIP's viewing condition in pixels per degree (default 67.02:\n"
           "0.7 m from a 0.7 m wide display of 3840 pixels)"},
          {"--heatmap", "", "OUT.png", "write FLIP's per-pixel error as a colour scale (flip, hdr-flip)"}}},
        helpOptions()};
}

void printCompareUsage() {
    std::fputs(
        "usage: fragpath compare TEST REFERENCE [--metric NAME] [--ppd X] [--heatmap OUT.png]\n"
        "\n"
        "Prints one line, the metric's name and its value (\"flip 0.0312\"). The images are .png (8-bit\n"
        "sRGB, decoded to linear), .exr, .pfm or .hdr (linear radiance), of the same size.\n"
        "FLIP (Andersson et al. 2020) is the perceived difference when flipping between the two images,\n"
        "0 (identical) to 1, averaged over pixels; flip clamps the linear values to [0, 1], as a display\n"
        "does, while hdr-flip (Andersson et al. 2021) tone maps both images at a range of exposures taken\n"
        "from the reference and keeps each pixel's largest error. rmse, relmse (relative MSE) and ssim are\n"
        "the noise study's metrics. The heat map's lightness rises evenly with the error, from black (0)\n"
        "through purple, red and orange to near white (1).\n"
        "\n"
        "exit status: 0 compared, 1 an image that cannot be read or images of different sizes, 2 a\n"
        "command line that cannot be read.\n",
        stdout);
    std::fputs(formatOptions(compareOptions()).c_str(), stdout);
}

bool isPng(const std::string& path) {
    return lowerCaseExtension(path) == ".png";
}

double pixelsPerDegreeOption(const Args& args) {
    auto text = args.text("--ppd");
    if (!text) return kDefaultPixelsPerDegree;
    std::optional<float> ppd;
    try {
        ppd = args.number("--ppd");
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    if (!(*ppd > 0.0f)) throw UsageError("option --ppd: pixels per degree must be positive, not " + *text);
    return *ppd;
}

}  // namespace

int compareCommand(const std::vector<std::string>& argv) {
    Args args(argv, compareOptions());
    if (args.wantsHelp()) {
        printCompareUsage();
        return 0;
    }
    if (args.positional().size() != 2)
        throw UsageError("compare needs two images, TEST and REFERENCE (see --help)");
    const std::string& testPath = args.positional()[0];
    const std::string& referencePath = args.positional()[1];
    const std::string metric =
        args.text("--metric").value_or(isPng(testPath) && isPng(referencePath) ? "flip" : "hdr-flip");
    if (std::find(kMetrics.begin(), kMetrics.end(), metric) == kMetrics.end())
        throw UsageError("unknown metric '" + metric + "' (choose " + choiceList(kMetrics) + ")");
    const bool flip = metric == "flip" || metric == "hdr-flip";
    const double ppd = pixelsPerDegreeOption(args);
    if (args.has("--ppd") && !flip) throw UsageError("option --ppd applies to flip and hdr-flip only");
    auto heatmap = args.text("--heatmap");
    if (heatmap && !flip) throw UsageError("option --heatmap applies to flip and hdr-flip only");
    if (heatmap && !isPng(*heatmap)) throw UsageError("option --heatmap: the error map is written as .png");
    if (heatmap) checkImageOutput(*heatmap, "--heatmap", true);

    const Image test = readImageOrPng(testPath);
    const Image reference = readImageOrPng(referencePath);
    double value = 0.0;
    if (flip) {
        const FlipResult r = metric == "flip" ? ldrFlip(test, reference, ppd) : hdrFlip(test, reference, ppd);
        value = r.mean;
        if (heatmap)
            writeFileAtomically(
                *heatmap, encodeRgb8Png(r.errorMap.width, r.errorMap.height, errorColorCodes(r.errorMap)));
    } else if (metric == "rmse") {
        value = rmse(test, reference);
    } else if (metric == "relmse") {
        value = relativeMse(test, reference);
    } else {
        value = ssim(test, reference);
    }
    std::printf("%s %.6g\n", metric.c_str(), value);
    return 0;
}

}  // namespace fp
