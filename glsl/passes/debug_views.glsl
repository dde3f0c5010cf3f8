// Debug views, chosen at compile time by DEBUG_VIEW (the values of fp::View in src/settings/render_settings.h).
// Geometry views show what the primary ray through the pixel centre (and the centre of a lens) hits (0
// on a miss); the cost views count what the path tracer does, averaged over the samples.
#include "common/intersect.glsl"
#include "common/surface.glsl"
#include INTEGRATOR_FILE
#include "passes/guides.glsl"

#define VIEW_DEPTH 1
#define VIEW_NORMAL 2
#define VIEW_ALBEDO 3
#define VIEW_BOUNCES 4
#define VIEW_NODES 5
#define VIEW_TRIANGLES 6
#define VIEW_COST 7

vec3 debugView(Ray ray) {
#if DEBUG_VIEW == VIEW_BOUNCES
    gBounces = 0;
    radiance(ray);  // the selected integrator, counting the bounces its path survives
    return vec3(float(gBounces));
#elif DEBUG_VIEW == VIEW_COST
    // What one whole path costs (the study's FLOP model, src/study/flop_model.h): BVH nodes visited,
    // triangles tested and surfaces shaded, summed over all of its rays.
    gPathNodes = 0;
    gPathTriangles = 0;
    gSurfacesShaded = 0;
    radiance(ray);
    return vec3(float(gPathNodes), float(gPathTriangles), float(gSurfacesShaded));
#else
    Hit hit;
    bool found = traceClosest(ray, hit);
#if DEBUG_VIEW == VIEW_NODES
    return vec3(float(gNodesVisited));  // BVH nodes the primary ray visited (each tests two boxes)
#elif DEBUG_VIEW == VIEW_TRIANGLES
    return vec3(float(gTrianglesTested));  // ray-triangle tests of the primary ray
#else
    if (!found) return vec3(0.0);
    Surface s = surfaceAt(ray, hit);
#if DEBUG_VIEW == VIEW_DEPTH
    return vec3(hit.t);  // distance along the unit-length ray
#elif DEBUG_VIEW == VIEW_NORMAL
    return 0.5 * s.shadingNormal + 0.5;  // the side facing the camera, mapped from [-1, 1] to [0, 1]
#else
    return surfaceAlbedo(s);  // passes/guides.glsl
#endif
#endif
#endif
}
