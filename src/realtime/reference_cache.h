#pragma once
// The references of `fragpath realtime --reference-spp K --reference-cache DIR`, kept on disk so that
// several runs over the same camera path (reuse on and off, filters, budgets) are judged against the
// same converged images without rendering them again: a K-spp reference costs K frames' worth of
// tracing, far more than the frame it judges.
//
// DIR/key.txt holds everything a reference depends on but the camera (scene, size, integrator, depth,
// seed, sampler, light sampling, clamp, K); DIR/reference_NNNN.exr (32-bit float, exact) and
// DIR/reference_NNNN.camera hold each frame's image and the camera it was rendered from. A cache made
// for other settings or another camera path is an error, never a silently wrong reference.
#include <optional>
#include <string>

#include "image/image.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace fp {

class ReferenceCache {
  public:
    // Creates DIR if needed; throws fp::Error if DIR holds a key.txt that differs from `key`.
    ReferenceCache(std::string dir, const std::string& key);

    // The reference of `frame`, if it is stored; throws fp::Error if it was stored for another camera.
    std::optional<Image> find(int frame, const Camera& camera) const;
    void store(int frame, const Camera& camera, const Image& reference) const;

    // What the key says about a render: every setting that changes its image, one per line.
    static std::string describe(const std::string& scene, const RenderSettings& settings, int referenceSpp);
    static std::string describe(const Camera& camera);

  private:
    std::string dir_;
    std::string framePath(int frame, const char* extension) const;
};

}  // namespace fp
