#pragma once
// The light a render gives a scene that brings none of its own, as a model viewer does. It sits in the
// request, after loading, because telling a room's lamp from glowing detail traces rays through the
// scene (request/own_light.h), which needs the BVH stage: scene -> BVH stays one way.
#include "scene/scene.h"

namespace fp {

// The light lightIfUnlit gives: the studio environment (scene/studio_environment.h), or, for the native
// reference, which has constant skies only, the uniform white sky (scene/lighting.h defaultSky).
enum class DefaultLight { Studio, UniformSky };

// Lights a scene that has no light of its own as a model viewer does: unless it has a punctual light or
// an environment that is not black, or emitters that light it (request/own_light.h: a closed room's
// lamp, not a glowing visor), it gets `light`, with a note (not a warning: it is the documented default,
// not a repair, so --strict does not refuse it) that says why and how to keep it dark (--environment
// none). Returns whether it did.
bool lightIfUnlit(Scene& scene, DefaultLight light = DefaultLight::Studio);

}  // namespace fp
