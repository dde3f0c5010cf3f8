// Normal maps without black rims. A mapped normal n that tilts far from the geometric normal ng mirrors
// a view direction wo below the true surface: a smooth metal's reflection there is a direction the path
// cannot follow (surface.glsl, sameSide), and the rims of normal-mapped bumps render black where the same
// bumps modelled as geometry show the environment. As Cycles does for its normal maps ("ensure valid
// reflection"), n is tilted back toward ng, in the plane of the two and no further than needed, until the
// reflection of wo rises at least a little above the surface. (The energy-conserving alternative,
// Schuessler, Hanika, Jung and Dachsbacher 2017, "Microfacet-based Normal Mapping for Robust Monte Carlo
// Path Tracing", replaces the BSDF by that of a two-facet microsurface in every integrator; the bend
// changes only the shading normal, which each integrator already reads.)
//
// With n = cos(theta) ng + sin(theta) x (x the unit direction of n's tilt) and wo = a x + b y + c ng, the
// reflection 2 (wo . n) n - wo has height c cos(2 theta) + a sin(2 theta) = A cos(2 theta - phi) above the
// surface, A = sqrt(a^2 + c^2), phi = atan(a, c). It is c > 0 at theta = 0 and at least `lowest` for
// |2 theta - phi| <= acos(lowest / A), so the largest tilt that keeps it there is (phi + acos(lowest / A)) / 2.
// `lowest` is Cycles' choice, min(0.9 c, 0.01): just above the horizon, and below the view's own height so
// that the untilted normal always qualifies. Then wo . n > 0 too: the view is above the shading normal.
// wo must be on ng's side (c > 0), as surfaceAt turns ng.
vec3 keepReflectionAbove(vec3 n, vec3 ng, vec3 wo) {
    float c = dot(wo, ng);
    float lowest = min(0.9 * c, 0.01);
    float viewCos = dot(wo, n);
    if (viewCos > 0.0 && 2.0 * viewCos * dot(n, ng) - c >= lowest) return n;
    vec3 x = n - dot(n, ng) * ng;
    if (!(dot(x, x) > 1e-12)) return ng;
    x = normalize(x);
    float a = dot(wo, x);
    float theta = 0.5 * (atan(a, c) + acos(clamp(lowest * inversesqrt(a * a + c * c), 0.0, 1.0)));
    return cos(theta) * ng + sin(theta) * x;
}

// The same for a direction w on either side of the surface (a path may arrive from the far side of a
// glass): n and ng turned to w's side, bent, and turned back.
vec3 keepReflectionAboveFor(vec3 n, vec3 ng, vec3 w) {
    float side = dot(w, ng) < 0.0 ? -1.0 : 1.0;
    return side * keepReflectionAbove(side * n, side * ng, w);
}
