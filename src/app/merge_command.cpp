// `fragpath merge`: combines partial renders (EXR files of disjoint sample ranges of one render) into
// the image a single render of all those samples gives.
#include <cstdio>

#include "app/commands.h"
#include "core/error.h"
#include "render/partial_render.h"
#include "request/render_request.h"

namespace fp {

namespace {

// The positional arguments are the parts, not a scene; only the display options apply.
FrontEndDefaults mergeDefaults() {
    FrontEndDefaults d;
    d.scene = false;
    return d;
}
const FrontEndDefaults kMergeDefaults = mergeDefaults();

std::vector<OptionGroup> mergeOptions() {
    std::vector<OptionGroup> groups = {
        {"Output", {{"--output", "-o", "FILE", "the merged image: .exr, .pfm or .png (by its extension)"}}}};
    for (OptionGroup& g : requestOptionGroups(kDisplayOptions)) groups.push_back(std::move(g));
    groups.push_back(helpOptions());
    return groups;
}

void printMergeUsage() {
    std::fputs(
        "usage: fragpath merge PART.exr PART.exr ... -o OUT.exr|OUT.pfm|OUT.png\n"
        "\n"
        "Averages partial renders weighted by their sample counts. The parts must come from the same scene\n"
        "and settings (their fingerprints must match) and hold disjoint sample ranges, as written by\n"
        "`fragpath render --sample-offset K --spp N -o part.exr`. The output's extension picks its format:\n"
        ".exr keeps the sample ranges (merge or --resume it again), .pfm the linear image, .png sRGB\n"
        "(tone-mapped as --exposure and --tonemap say). An .exr output keeps each AOV layer (render --aovs)\n"
        "that every part has, averaged the same way.\n",
        stdout);
    std::fputs(formatOptions(mergeOptions()).c_str(), stdout);
}

}  // namespace

int mergeCommand(const std::vector<std::string>& argv) {
    Args args(argv, mergeOptions());
    if (args.wantsHelp()) {
        printMergeUsage();
        return 0;
    }
    auto output = args.text("--output");
    if (!output) throw Error("merge needs an output file: -o OUT.exr");
    if (args.positional().empty()) throw Error("merge needs the partial renders to combine");
    std::vector<PartialRender> parts;
    for (const std::string& path : args.positional()) parts.push_back(readPartial(path));
    PartialRender merged = mergePartials(parts, args.positional());
    writeRenderOutput(*output, merged, RenderRequest(args, kMergeDefaults).display());
    std::fprintf(stderr, "%s: %llu samples per pixel from %zu parts\n", output->c_str(),
                 (unsigned long long)merged.samples(), parts.size());
    return 0;
}

}  // namespace fp
