#include "scene/punctual_light.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/text.h"

namespace fp {

const char* punctualLightTypeName(PunctualLightType type) {
    static constexpr const char* kNames[] = {"point", "spot", "directional"};  // in enum order
    return nameOf(type, kNames);
}

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

constexpr float kHalfPi = 1.57079633f;  // pi / 2 rounded up to a float, so that glTF's pi / 2 passes

}  // namespace

void validatePunctualLight(const PunctualLight& light, const std::string& where) {
    const char* type = punctualLightTypeName(light.type);
    if (!finite(light.intensity)) throw Error(where + " (" + type + "): the intensity must be finite");
    if (light.intensity.x < 0.0f || light.intensity.y < 0.0f || light.intensity.z < 0.0f)
        throw Error(where + " (" + type + "): the intensity must not be negative");
    if (light.type != PunctualLightType::Directional && !finite(light.position))
        throw Error(where + " (" + type + "): the position must be finite");
    if (light.type != PunctualLightType::Point) {
        if (!finite(light.direction)) throw Error(where + " (" + type + "): the direction must be finite");
        float length = glm::length(light.direction);
        if (!(std::abs(length - 1.0f) < 1e-4f))
            throw Error(where + " (" + type + "): the direction must be a unit vector (length " +
                        std::to_string(length) + ")");
    }
    if (light.type == PunctualLightType::Spot) {
        float inner = light.innerConeAngle, outer = light.outerConeAngle;
        if (!std::isfinite(inner) || !std::isfinite(outer))
            throw Error(where + " (spot): the cone angles must be finite");
        if (!(inner >= 0.0f && inner < outer && outer <= kHalfPi))
            throw Error(where +
                        " (spot): the cone angles must satisfy 0 <= inner < outer <= 90 degrees, got " +
                        std::to_string(inner * 180.0f / 3.14159265f) + " and " +
                        std::to_string(outer * 180.0f / 3.14159265f));
    }
}

float spotFalloff(float cosTheta, float cosInner, float cosOuter) {
    float t = std::clamp((cosTheta - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
    return t * t;
}

double spotSolidAngle(float innerConeAngle, float outerConeAngle) {
    double cosInner = std::cos(double(innerConeAngle)), cosOuter = std::cos(double(outerConeAngle));
    return 2.0 * 3.14159265358979324 * ((1.0 - cosInner) + (cosInner - cosOuter) / 3.0);
}

BoundingSphere directionalLightSphere(const Scene& scene) {
    Aabb bounds = scene.bounds();
    BoundingSphere sphere;
    if (bounds.empty()) return sphere;
    glm::dvec3 lo(bounds.lo), hi(bounds.hi);
    sphere.centre = glm::vec3(0.5 * (lo + hi));
    sphere.radius = float(0.5 * glm::length(hi - lo) * (1.0 + 1e-3));
    return sphere;
}

std::string describePunctualLight(const PunctualLight& l) {
    char text[256];
    std::string name = l.name.empty() ? "" : " '" + l.name + "'";
    const glm::vec3 &p = l.position, &d = l.direction, &i = l.intensity;
    const double deg = 180.0 / 3.14159265358979324;
    switch (l.type) {
        case PunctualLightType::Point:
            std::snprintf(text, sizeof text, "(%.3g, %.3g, %.3g), I = %.3g, %.3g, %.3g W/sr", double(p.x),
                          double(p.y), double(p.z), double(i.x), double(i.y), double(i.z));
            break;
        case PunctualLightType::Spot:
            std::snprintf(
                text, sizeof text,
                "(%.3g, %.3g, %.3g) -> (%.3g, %.3g, %.3g), %.3g-%.3g deg, I = %.3g, %.3g, %.3g W/sr",
                double(p.x), double(p.y), double(p.z), double(d.x), double(d.y), double(d.z),
                double(l.innerConeAngle) * deg, double(l.outerConeAngle) * deg, double(i.x), double(i.y),
                double(i.z));
            break;
        case PunctualLightType::Directional:
            std::snprintf(text, sizeof text, "-> (%.3g, %.3g, %.3g), E = %.3g, %.3g, %.3g W/m^2", double(d.x),
                          double(d.y), double(d.z), double(i.x), double(i.y), double(i.z));
            break;
    }
    return std::string(punctualLightTypeName(l.type)) + name + ": " + text;
}

}  // namespace fp
