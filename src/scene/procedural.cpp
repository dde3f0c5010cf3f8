#include "scene/procedural.h"

#include <algorithm>
#include <cmath>

namespace fp {

void appendSphere(Scene& scene, const glm::vec3& center, float radius, int rings, int segments, uint32_t material,
                  bool smooth) {
    rings = std::max(rings, 2);
    segments = std::max(segments, 3);
    const float pi = 3.14159265358979f;
    // Unit direction of grid point (ring r from the north pole, segment s).
    auto direction = [&](int r, int s) {
        float theta = pi * float(r) / float(rings), phi = 2.0f * pi * float(s % segments) / float(segments);
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    auto add = [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        Triangle t;
        t.p = {center + radius * a, center + radius * b, center + radius * c};
        t.material = material;
        glm::vec3 n = glm::normalize(t.geometricNormal());
        t.n = smooth ? std::array<glm::vec3, 3>{a, b, c} : std::array<glm::vec3, 3>{n, n, n};
        scene.triangles.push_back(t);
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            glm::vec3 a = direction(r, s), b = direction(r, s + 1), c = direction(r + 1, s), d = direction(r + 1, s + 1);
            // Counter-clockwise from outside; the caps have one triangle per segment, the bands two.
            if (r > 0) add(a, b, d);
            if (r < rings - 1) add(a, d, c);
        }
}

}  // namespace fp
