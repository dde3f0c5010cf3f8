// build/fragpath_native: the native reference on its own (benchmark only; src/native/native_scene.h
// says what it is). Renders a diffuse scene on one thread and prints paths per CPU-second, the figure
// `fragpath bench --native` compares the fragment shader with.
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/image.h"
#include "native/native_path.h"
#include "pack/layout.h"
#include "request/render_request.h"

namespace {

// One final image, as `fragpath render` makes, but 1 spp unless asked: the reference is slow.
constexpr unsigned kNativeOptions =
    fp::kSizeOption | fp::kSppOption | fp::kPathOptions | fp::kCameraOptions | fp::kSceneOptions;

fp::FrontEndDefaults nativeDefaults() {
    fp::FrontEndDefaults d;
    d.own.set("spp", 1);
    d.ignoresSceneFile = fp::kSppOption;
    d.defaultLight = fp::DefaultLight::UniformSky;  // constant skies only (native_scene.cpp)
    return d;
}

std::vector<fp::OptionGroup> nativeOptions() {
    std::vector<fp::OptionGroup> groups = {
        {"Output", {{"--output", "-o", "FILE", "write the mean image (.pfm, .exr or .png)"}}}};
    for (fp::OptionGroup& g : fp::requestOptionGroups(kNativeOptions, nativeDefaults()))
        groups.push_back(std::move(g));
    groups.push_back(fp::helpOptions());
    return groups;
}

int run(const std::vector<std::string>& argv) {
    fp::Args args(argv, nativeOptions());
    if (args.wantsHelp()) {
        std::fputs(
            "usage: fragpath_native [SCENE] [options]\n"
            "\n"
            "A single-threaded scalar C++ path tracer of the same algorithm as fragpath's default "
            "integrator\n"
            "(next-event estimation with MIS, Lambertian surfaces only, independent random numbers), on the\n"
            "same BVH. SCENE defaults to the built-in Cornell box. Prints paths per CPU-second.\n",
            stdout);
        std::fputs(fp::formatOptions(nativeOptions()).c_str(), stdout);
        return 0;
    }
    const fp::RenderRequest request(args, nativeDefaults());
    fp::Scene scene = request.loadScene();
    const fp::RenderSettings render = request.settings(scene);
    if (render.integrator != fp::Integrator::Nee)
        throw fp::Error(std::string("the scene file asks for integrator ") +
                        fp::integratorName(render.integrator) + "; fragpath_native implements only nee");
    fp::native::Settings settings;
    settings.width = render.width;
    settings.height = render.height;
    settings.maxDepth = render.maxDepth;
    settings.seed = render.seed;
    settings.spp = request.spp(scene);
    const fp::Camera camera = request.camera(scene);

    fp::native::Result r =
        fp::native::render(fp::native::buildScene(scene, fp::layout::bvhOptions()), camera, settings);
    std::printf("native: %dx%d %d spp depth %d: %.4g paths/cpu-s, %.4g rays/cpu-s (%.3f cpu s, one thread)\n",
                settings.width, settings.height, settings.spp, settings.maxDepth, r.paths / r.cpuSeconds,
                r.rays / r.cpuSeconds, r.cpuSeconds);
    if (auto out = args.text("--output")) {
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
    } catch (const fp::UsageError& e) {
        std::fprintf(stderr, "fragpath_native: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fragpath_native: error: %s\n", e.what());
        return 1;
    }
}
