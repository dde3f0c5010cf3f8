// Debug views: what the primary ray through the pixel centre hits, one quantity per view, chosen at
// compile time by DEBUG_VIEW (the values of fp::View in src/render/settings.h). A miss shows 0.
#define VIEW_DEPTH 1
#define VIEW_NORMAL 2
#define VIEW_ALBEDO 3

vec3 debugView(Ray ray) {
    Hit hit;
    if (!traceClosest(ray, hit)) return vec3(0.0);
    Surface s = surfaceAt(ray, hit);
#if DEBUG_VIEW == VIEW_DEPTH
    return vec3(hit.t);  // distance along the unit-length ray
#elif DEBUG_VIEW == VIEW_NORMAL
    return 0.5 * s.shadingNormal + 0.5;  // the side facing the camera, mapped from [-1, 1] to [0, 1]
#else
    return materialAlbedo(s.material);
#endif
}
