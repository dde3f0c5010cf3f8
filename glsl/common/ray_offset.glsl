// Where a ray leaving a surface starts, and where a shadow ray between two surface points ends, so that
// neither finds the surface it belongs to (self-intersection) nor misses anything else.
//
// A hit point computed from its barycentrics, v0 + b1 e1 + b2 e2, lies within a few ulps of the largest
// vertex coordinate of the true triangle, and the Moller-Trumbore distance of a ray starting next to the
// plane errs by as much; both errors scale with the magnitude of the coordinates, not with the scene's
// size or the length of the ray (Wachter & Binder 2019, "A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6; pbrt-v4 section 6.8.6). So each surface point carries an
// offset distance of 2^-18 of its triangle's largest vertex coordinate (about 30 ulps), and rays leave
// from the point moved that far along the geometric normal, on the side they leave on. A shadow ray is
// offset that way at BOTH ends and stops exactly at its far end's offset point: a fraction of its length
// (the usual t < (1 - eps) dist) is shorter than the offset whenever the two points are close together
// or far from the origin, and the ray then finds the light it was aimed at and calls it a blocker.
#include "common/scene_data.glsl"
#include "common/intersect.glsl"

const float RAY_OFFSET_SCALE = 1.0 / 262144.0;

float surfaceOffset(TriangleData tri) {
    vec3 m = abs(tri.v0) + max(abs(tri.e1), abs(tri.e2));  // bounds every vertex's coordinates
    return RAY_OFFSET_SCALE * max(m.x, max(m.y, m.z));
}

// p moved by `offset` along the unit normal n, to the side `toward` points to.
vec3 offsetToward(vec3 p, vec3 n, float offset, vec3 toward) {
    return p + (dot(toward, n) >= 0.0 ? offset : -offset) * n;
}

// The shadow ray between surface points a and b (normals na, nb; offsets as surfaceOffset gives; an
// offset of 0 for a point on no surface, like a pinhole): from a's offset point, reaching b's at tMax.
// False when the points are closer than their offsets (touching surfaces): nothing lies between them.
bool shadowRayBetween(vec3 a, vec3 na, float offsetA, vec3 b, vec3 nb, float offsetB, out Ray ray, out float tMax) {
    vec3 d = b - a;
    vec3 from = offsetToward(a, na, offsetA, d), to = offsetToward(b, nb, offsetB, -d);
    vec3 e = to - from;
    tMax = length(e);
    ray = Ray(from, e / tMax);
    return dot(e, d) > 0.0;
}

bool segmentOccluded(vec3 a, vec3 na, float offsetA, vec3 b, vec3 nb, float offsetB) {
    Ray ray;
    float tMax;
    return shadowRayBetween(a, na, offsetA, b, nb, offsetB, ray, tMax) && occluded(ray, tMax);
}
