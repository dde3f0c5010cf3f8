#pragma once
// A render split into sample ranges (for clusters, time budgets and resuming): which samples an EXR
// holds, and a fingerprint of everything that determines the image, stored in the EXR header so that
// partial results of different scenes or settings are never combined.
#include <cstdint>
#include <string>
#include <vector>

#include "image/exr.h"
#include "image/image.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace fp {

struct SampleRange {
    uint64_t first = 0, count = 0;  // sample indices [first, first + count) at every pixel
    uint64_t end() const { return first + count; }
};

struct PartialRender {
    Image mean;                       // per pixel, the mean of its samples
    std::vector<SampleRange> ranges;  // disjoint, sorted
    std::string fingerprint;
    uint64_t samples() const;
};

// Everything that determines the image: geometry, materials, environment, camera and the settings
// (size, depth, integrator, view, seed). Sample counts and ranges are not part of it.
std::string renderFingerprint(const Scene& scene, const RenderSettings& settings, const Camera& camera);

void writePartial(const std::string& path, const PartialRender& partial);
// A render's output by the extension of path: .exr keeps the sample ranges and fingerprint
// (writePartial: it can be merged or resumed); .pfm gets the mean image, .png the mean as `view` shows
// it (writeRenderedView: a heat map for counts, depth scaled to its far end).
void writeRenderOutput(const std::string& path, const PartialRender& partial,
                       const DisplaySettings& display = {}, View view = View::Radiance);
// Throws fp::Error naming the file when it is not an EXR written by fragpath (no sample ranges).
PartialRender readPartial(const std::string& path);

// Sample-weighted average of partial renders. Throws fp::Error naming the files when fingerprints or
// sizes differ or sample ranges overlap.
PartialRender mergePartials(const std::vector<PartialRender>& parts, const std::vector<std::string>& names);

}  // namespace fp
