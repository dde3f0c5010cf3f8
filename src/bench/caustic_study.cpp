#include "bench/caustic_study.h"

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/clock.h"
#include "gl/context.h"
#include "image/image_stats.h"
#include "render/renderer.h"
#include "scene/procedural.h"

namespace fp::bench {

namespace {

constexpr int kSize = 24;  // kCausticUnderSphere is given for this size
constexpr int kMaxDepth = 5;

}  // namespace

Image cropImage(const Image& image, const PixelRect& r) {
    Image out(r.width, r.height);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) out.at(x, y) = image.at(r.x + x, r.y + y);
    return out;
}

double regionVariance(const Accumulation& acc, const PixelRect& r) {
    return meanColor(acc.varianceOfMean(), r).y * double(r.width) * double(r.height);
}

RenderSettings causticStudySettings(Integrator integrator, uint32_t seed, Caustics caustics) {
    RenderSettings s;
    s.width = s.height = kSize;
    s.integrator = integrator;
    s.caustics = caustics;
    s.maxDepth = kMaxDepth;
    s.seed = seed;
    s.samplesPerPass = 16;
    return s;
}

int runCausticStudy(const CausticStudyOptions& options) {
    std::unique_ptr<GlContext> context = createOsMesaContext();
    const PixelRect region = kCausticUnderSphere;
    std::printf(
        "caustic study: %dx%d, depth %d, %.0f s of process CPU time per integrator, back to back;\n"
        "reference: bdpt, %d spp, seed 99. RMSE over the image and under the sphere (%dx%d pixels);\n"
        "var: variance of the mean summed over the pixels under the sphere (luminance channel G).\n",
        kSize, kSize, kMaxDepth, options.budgetSeconds, options.referenceSpp, region.width, region.height);
    for (float roughness : {0.0f, 0.3f}) {
        Scene scene = causticScene(roughness);
        Renderer renderer(scene);
        renderer.configure(causticStudySettings(Integrator::Bdpt, 99), *scene.camera);
        renderer.render(options.referenceSpp);
        Accumulation reference = renderer.readback();
        Image ref = reference.mean();
        std::printf(
            "\nglass roughness %.1f; the reference's own standard error under the sphere: %.5f (RMS)\n",
            roughness, std::sqrt(regionVariance(reference, region) / (region.width * region.height)));
        std::printf(
            "  integrator      spp   cpu s  wall s  RMSE image  RMSE under sphere  var under sphere\n");
        struct Contender {
            const char* name;
            Integrator integrator;
            Caustics caustics;
        };
        // nee by camera paths alone and with its light pass (smooth glass only: rough glass has no delta
        // lobe to aim at), and bdpt.
        for (const Contender& c : {Contender{"nee", Integrator::Nee, Caustics::Path},
                                   Contender{"nee+light", Integrator::Nee, Caustics::Light},
                                   Contender{"bdpt", Integrator::Bdpt, Caustics::Auto}}) {
            if (c.caustics == Caustics::Light && roughness > 0.0f) continue;
            renderer.configure(causticStudySettings(c.integrator, 7, c.caustics), *scene.camera);
            renderer.render(16);  // warm-up: shader JIT
            renderer.configure(causticStudySettings(c.integrator, 7, c.caustics), *scene.camera);
            double cpuStart = processCpuSeconds(), cpu = 0.0;
            auto wallStart = SteadyClock::now();
            while (cpu < options.budgetSeconds) {
                renderer.render(16);
                cpu = processCpuSeconds() - cpuStart;
            }
            double wall = secondsSince(wallStart);
            Accumulation acc = renderer.readback();
            Image mean = acc.mean();
            std::printf("  %-10s %8d %7.1f %7.1f %11.5f %18.5f %17.4g\n", c.name, renderer.samples(), cpu,
                        wall, rmse(mean, ref), rmse(cropImage(mean, region), cropImage(ref, region)),
                        regionVariance(acc, region));
        }
    }
    return 0;
}

}  // namespace fp::bench
