// build/fragpath_native: the native reference on its own (benchmark only; src/native/native_scene.h
// says what it is). Renders a diffuse scene on one thread and prints paths per CPU-second, the figure
// `fragpath bench --native` compares the fragment shader with.
#include <cstdio>
#include <string>
#include <vector>

#include "app/args.h"
#include "core/error.h"
#include "pack/layout.h"
#include "image/image.h"
#include "native/native_path.h"
#include "scene/builtin_scene.h"
#include "scene/load.h"

namespace {

const char* kUsage =
    "usage: fragpath_native [SCENE] [--size WxH] [--spp N] [--max-depth D] [--seed S] [-o FILE]\n"
    "\n"
    "A single-threaded scalar C++ path tracer of the same algorithm as fragpath's default integrator\n"
    "(next-event estimation with MIS, Lambertian surfaces only), on the same BVH. SCENE defaults to the\n"
    "built-in Cornell box; size 512x512, 1 spp, depth 5, seed 0. Prints paths per CPU-second; -o writes\n"
    "the mean image (.pfm, .exr or .png).\n";

int run(const std::vector<std::string>& argv) {
    fp::Args args(argv, {"--size", "--spp", "--max-depth", "--seed", "-o"}, {"-h", "--help"});
    if (args.has("-h") || args.has("--help")) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    if (args.positional().size() > 1) throw fp::Error("fragpath_native takes at most one scene file");
    fp::Scene scene =
        args.positional().empty() ? fp::builtinCornellBox() : fp::loadScene(args.positional()[0]);
    fp::native::Settings settings;
    if (auto s = args.size("--size")) settings.width = s->x, settings.height = s->y;
    settings.spp = args.integer("--spp", 1, 1 << 20).value_or(1);
    settings.maxDepth = args.integer("--max-depth", 0, 1000).value_or(5);
    settings.seed = uint32_t(args.integer("--seed", 0, 1 << 30).value_or(0));
    fp::Camera camera = scene.camera.value_or(fp::frameBounds(scene.bounds()));

    fp::native::Result r =
        fp::native::render(fp::native::buildScene(scene, fp::layout::bvhOptions()), camera, settings);
    std::printf("native: %dx%d %d spp depth %d: %.4g paths/cpu-s, %.4g rays/cpu-s (%.3f cpu s, one thread)\n",
                settings.width, settings.height, settings.spp, settings.maxDepth, r.paths / r.cpuSeconds,
                r.rays / r.cpuSeconds, r.cpuSeconds);
    if (auto out = args.text("-o")) {
        fp::Image image(r.width, r.height);
        for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = glm::vec3(r.sum[i]) / r.sum[i].w;
        fp::writeImage(*out, image);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fragpath_native: error: %s\n", e.what());
        return 1;
    }
}
