#pragma once
// AOVs ("arbitrary output variables"): first-hit layers that `fragpath render --aovs` writes into an
// .exr output next to the beauty, for compositors and for external denoisers such as Intel Open Image
// Denoise (OIDN). They are the denoisers' first-hit guides (glsl/passes/guides.glsl, accumulated when
// RenderSettings::guides is set), traced along the same jittered camera rays as the beauty and
// averaged over the same samples, so they are anti-aliased the way the beauty is (as OIDN asks).
//
//   --aovs   EXR channels                 per pixel, the mean over its samples of
//   albedo   albedo.R albedo.G albedo.B   the first hit's diffuse reflectance (MTL Kd, times its
//                                         texture); 0 for a miss
//   normal   normal.X normal.Y normal.Z   the first hit's shading normal in WORLD space, on the side
//                                         facing the camera; 0 for a miss. Not renormalised: unit
//                                         length inside a flat surface, shorter where a pixel spans
//                                         an edge (OIDN wants the mean of unit normals, in world or
//                                         view space, values in [-1, 1])
//   depth    depth.Z                      the distance from the eye along the camera ray to the first
//                                         hit, in scene units (not the z of the camera's axis); the
//                                         mean over the samples that hit something; 0 where none did
//
// Naming: a single-part EXR keeps the beauty in the unprefixed R, G, B channels that every reader
// shows, and each AOV as a layer by OpenEXR's "layer.channel" convention. The layer names are OIDN's
// image names (`albedo`, `normal`); a vector's components are X, Y, Z and depth is Z, as in Blender
// Cycles' Normal and Depth passes (Normal.X, Depth.Z) and Nuke's built-in depth.Z. To feed OIDN's
// oidnDenoise, which takes one image per file: oiiotool out.exr --ch albedo.R,albedo.G,albedo.B -o
// albedo.pfm (and likewise normal.X,normal.Y,normal.Z, and R,G,B for the beauty).
#include <optional>
#include <string>
#include <vector>

#include "image/exr.h"
#include "image/image.h"
#include "render/accumulation.h"

namespace fp {

enum class Aov { Albedo, Normal, Depth };

struct AovImage {
    Aov aov;
    Image image;  // per pixel, components in the order of aovChannels (depth: component 0 only)
};

const std::vector<Aov>& allAovs();
const char* aovName(Aov aov);  // the --aovs name and the EXR layer name
// The EXR channel names of the layer, in component order: R, G, B; X, Y, Z; Z.
std::vector<std::string> aovChannels(Aov aov);

// "albedo,normal,depth": the named AOVs in the order given. Throws fp::Error listing the choices for an
// unknown name, and for an empty or repeated one (splitNameList, core/text.h).
std::vector<Aov> parseAovs(const std::string& list);
// The value of --aovs for a render written to `output` (none without the flag). Throws fp::Error
// unless `output` is an .exr file, the only format with room for them.
std::vector<Aov> parseAovOption(const std::optional<std::string>& list, const std::string& output);

// The AOVs' means over the guide samples of an accumulation rendered with guides.
std::vector<AovImage> aovImages(const Accumulation& acc, const std::vector<Aov>& aovs);

// One render's AOVs and, per pixel, the samples behind them.
struct AovPart {
    const std::vector<AovImage>* aovs;
    std::vector<double> samples;  // per pixel, or a single value for every pixel
};
// `aov` of the parts that have it, combined as one render of all their samples would give it: the
// per-pixel means weighted by samples (depth: only the parts with a hit at that pixel, depth 0 meaning
// none, since depth averages over hits). std::nullopt when no part has it or its parts hold no samples.
std::optional<AovImage> combineAov(Aov aov, const std::vector<AovPart>& parts);

ExrLayer toExrLayer(const AovImage& aov);
// The layers of a file that are AOVs (named and with the channels above); any other layer is ignored.
std::vector<AovImage> aovsFromExrLayers(const std::vector<ExrLayer>& layers);

}  // namespace fp
