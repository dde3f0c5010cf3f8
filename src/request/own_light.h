#pragma once
// Whether a scene's emitters light it, or are only glowing detail: a room lit by its lamp (the Cornell
// box) keeps its own light, while a helmet whose visor glows, or a model with an emissive texture over
// most of it, gets the studio environment as a model viewer would (request/default_light.h lightIfUnlit).
//
// Two measures, each estimated with a fixed number of CPU rays (bvh/ray_query.h) at a fixed seed, so
// the answer is the same on every run:
// - enclosure: of the light the emitters send out (paths started on their front faces in proportion to
//   power, cosine-distributed), the fraction that meets the scene's surfaces at each of its first
//   kEnclosureBounces bounces instead of leaving to infinity (albedo ignored; each bounce cosine-
//   distributed about the side the path arrived on). About 0.6 for the Cornell box, whose open front
//   lets some light out; near 0 for emissive detail on a model's outside, whose light leaves at once;
//   low too for a lamp inside a reflector on an otherwise open model, whose light leaves at the second
//   bounce.
// - ownToStudio: at points spread over the scene's surfaces by area (front faces, cosine-distributed
//   directions), the radiance the scene's emitters send them over the radiance the studio environment
//   (scene/studio_environment.h) would send them where the rays leave the scene. Above 1 for a floor
//   under a bright lamp, whatever the surroundings; small for a dim glow.
// The emitters light the scene when either measure reaches its threshold.
#include "scene/scene.h"

namespace fp {

constexpr int kEnclosureBounces = 2;
constexpr double kEnclosedThreshold = 0.4;
constexpr double kOwnToStudioThreshold = 0.5;
constexpr int kOwnLightSamples = 4096;  // paths for each measure: a standard error below 0.01 for a fraction

struct OwnLightEstimate {
    double enclosure = 0.0;
    double ownToStudio = 0.0;
    bool lightsTheScene() const {
        return enclosure >= kEnclosedThreshold || ownToStudio >= kOwnToStudioThreshold;
    }
};

// The two measures for `scene`'s emitter triangles (emission times its map's mean, as light selection
// weighs them: scene/light_selection.h). A scene without emitters gets zeros. Instances are placed in
// the world for the rays (their meshes emit nothing, but they block and reflect).
OwnLightEstimate estimateOwnLight(const Scene& scene, int samples = kOwnLightSamples);

}  // namespace fp
