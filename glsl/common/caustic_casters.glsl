// Where nee's light pass aims its light paths (CAUSTICS_LIGHT_TRACED: integrators/nee.glsl). A caustic
// path's first bounce after the light is on a surface with a delta lobe (smooth glass, a mirror), and the
// renderer bounds those surfaces, the caustic casters, by a few spheres (src/pack/caustic_casters.h).
// Light paths leave the light only inside the cones the spheres subtend from it: no caustic path lies
// outside them, so no caustic is lost, and no light path is spent on the rest of the scene (Jensen's
// "projection maps", Realistic Image Synthesis Using Photon Mapping, 2001, section 9.2).
#include "common/sampling.glsl"

uniform vec4 uCasters[MAX_CAUSTIC_CASTERS];  // (centre, radius) of each sphere
uniform int uCasterCount;

// The cosine of the half-angle of the cone sphere c subtends from p: -1 (every direction) from inside it.
float casterConeCos(vec4 c, vec3 p) {
    vec3 d = c.xyz - p;
    float d2 = dot(d, d);
    return d2 <= c.w * c.w ? -1.0 : sqrt(max(0.0, 1.0 - c.w * c.w / d2));
}

// A direction from p uniform over the union of the cones, counted with multiplicity: a cone is chosen in
// proportion to its solid angle, then a direction uniformly inside it. pdf: the solid-angle density of
// that direction, the number of cones that hold it over their total solid angle.
vec3 sampleTowardCasters(vec3 p, vec2 u, out float pdf) {
    float total = 0.0;
    for (int i = 0; i < uCasterCount; ++i) total += 1.0 - casterConeCos(uCasters[i], p);
    float target = u.x * total;
    int pick = uCasterCount - 1;
    for (int i = 0; i < uCasterCount; ++i) {
        float w = 1.0 - casterConeCos(uCasters[i], p);
        if (target < w || i == uCasterCount - 1) {
            pick = i;
            u.x = clamp(target / w, 0.0, 1.0);  // rescaled, so the pair stays stratified
            break;
        }
        target -= w;
    }
    vec4 c = uCasters[pick];
    float cosMax = casterConeCos(c, p);
    vec3 axis = cosMax > -1.0 ? normalize(c.xyz - p) : vec3(0.0, 0.0, 1.0);
    vec3 dir = sampleUniformCone(axis, cosMax, u);
    float holding = 1.0;  // the picked cone holds dir, whatever the rounding at its edge
    for (int i = 0; i < uCasterCount; ++i) {
        float cosI = casterConeCos(uCasters[i], p);
        if (i != pick && (cosI == -1.0 || dot(dir, normalize(uCasters[i].xyz - p)) >= cosI)) holding += 1.0;
    }
    pdf = holding / (2.0 * PI * total);
    return dir;
}

// For a directional light, whose rays all travel along unit `dir`: a ray origin on the plane through
// `planePoint` perpendicular to dir, uniform over the union of the disks the spheres cast on it (one
// chosen in proportion to its area, counted with multiplicity). pdf: the area density of that point,
// the number of disks that hold it over their total area.
vec3 sampleAlongToCasters(vec3 dir, vec3 planePoint, vec2 u, out float pdf) {
    float total = 0.0;
    for (int i = 0; i < uCasterCount; ++i) total += uCasters[i].w * uCasters[i].w;
    float target = u.x * total;
    int pick = uCasterCount - 1;
    for (int i = 0; i < uCasterCount; ++i) {
        float w = uCasters[i].w * uCasters[i].w;
        if (target < w || i == uCasterCount - 1) {
            pick = i;
            u.x = clamp(target / w, 0.0, 1.0);
            break;
        }
        target -= w;
    }
    vec3 t, b;
    orthonormalBasis(dir, t, b);
    vec3 c = uCasters[pick].xyz;
    vec3 centre = c - dot(c - planePoint, dir) * dir;  // the sphere's centre, projected on the plane
    vec2 d = uCasters[pick].w * sampleConcentricDisk(u);
    vec3 origin = centre + d.x * t + d.y * b;
    float holding = 1.0;  // the picked disk holds the point, whatever the rounding at its edge
    for (int i = 0; i < uCasterCount; ++i) {
        vec3 q = uCasters[i].xyz - planePoint;
        vec3 offset = (origin - planePoint) - (q - dot(q, dir) * dir);
        if (i != pick && dot(offset, offset) <= uCasters[i].w * uCasters[i].w) holding += 1.0;
    }
    pdf = holding / (PI * total);
    return origin;
}
