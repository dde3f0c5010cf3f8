#pragma once
// A render split into sample ranges (for clusters, time budgets and resuming): which samples an EXR
// holds, and a fingerprint of everything that determines the image, stored in the EXR header so that
// partial results of different scenes or settings are never combined.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/exr.h"
#include "image/image.h"
#include "render/accumulation.h"
#include "render/aovs.h"
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
    std::vector<AovImage> aovs;  // first-hit layers over the same samples (render/aovs.h), if any
    uint64_t samples() const;
};

// Everything that determines the image: geometry, materials, environment, camera and the settings
// (size, depth, integrator, view, seed). Sample counts and ranges are not part of it.
std::string renderFingerprint(const Scene& scene, const RenderSettings& settings, const Camera& camera);

// The AOVs (albedo.R, normal.X, ...) become layers of the EXR next to the beauty's R, G, B.
void writePartial(const std::string& path, const PartialRender& partial);
// A render's output by the extension of path: .exr keeps the sample ranges and fingerprint
// (writePartial: it can be merged or resumed); .pfm gets the mean image, .png the mean as `view` shows
// it (writeRenderedView: a heat map for counts, depth scaled to its far end); neither has AOVs.
void writeRenderOutput(const std::string& path, const PartialRender& partial,
                       const DisplaySettings& display = {}, View view = View::Radiance);
// Throws fp::Error naming the file when it is not an EXR written by fragpath (no sample ranges). Reads
// the AOV layers it has; other extra layers are ignored.
PartialRender readPartial(const std::string& path);

// Sample-weighted average of partial renders. Throws fp::Error naming the files when fingerprints or
// sizes differ or sample ranges overlap. Carries the AOVs that every part has, combined the same way
// (combineAov); an AOV some part lacks is dropped, since it would not cover all the samples.
PartialRender mergePartials(const std::vector<PartialRender>& parts, const std::vector<std::string>& names);

// The AOVs of a render's output: those of `acc` (rendered with guides, over the samples rendered now),
// combined with the same AOV of the resumed file when it has it (a file without it leaves the samples
// rendered now). Throws fp::Error when an AOV covers no samples at all (a resumed file without it and
// nothing left to render).
std::vector<AovImage> outputAovs(const Accumulation& acc, const std::vector<Aov>& aovs,
                                 const std::optional<PartialRender>& resumed);

}  // namespace fp
