// Sampling routines and their densities.
const float PI = 3.14159265358979324;

// An orthonormal basis around unit n: Duff et al. 2017, "Building an Orthonormal Basis, Revisited".
void orthonormalBasis(vec3 n, out vec3 t, out vec3 b) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

vec3 toWorld(vec3 local, vec3 n) {
    vec3 t, b;
    orthonormalBasis(n, t, b);
    return local.x * t + local.y * b + local.z * n;
}

// Uniform over the hemisphere around n; pdf = 1 / (2 pi) (pbrt-v4 A.5.2).
vec3 sampleUniformHemisphere(vec3 n, vec2 u) {
    float z = u.x;
    float r = sqrt(max(0.0, 1.0 - z * z));
    float phi = 2.0 * PI * u.y;
    return toWorld(vec3(r * cos(phi), r * sin(phi), z), n);
}

// Uniform over the whole sphere; pdf = 1 / (4 pi) (pbrt-v4 A.5.2).
vec3 sampleUniformSphere(vec2 u) {
    float z = 1.0 - 2.0 * u.x, r = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

// Uniform inside the cone of directions within angle acos(cosMax) of unit `axis`; pdf = 1 / (2 pi (1 -
// cosMax)) (pbrt-v4 A.5.4). cosMax = -1 is the whole sphere.
vec3 sampleUniformCone(vec3 axis, float cosMax, vec2 u) {
    float z = 1.0 - u.x * (1.0 - cosMax), r = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * PI * u.y;
    return toWorld(vec3(r * cos(phi), r * sin(phi), z), axis);
}

// Cosine-weighted around +z, the normal of the local shading frame (Malley's method: uniform on the
// disk, projected up); pdf = cos(theta) / pi (pbrt-v4 A.5.3).
vec3 sampleCosineLocal(vec2 u) {
    float r = sqrt(u.x);
    float phi = 2.0 * PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
}

// Uniform on the unit disc by Shirley & Chiu's concentric map (1997, "A Low Distortion Map Between Disk
// and Square"; pbrt-v4 A.5.1): concentric squares of [-1, 1]^2 go to concentric circles, area-preserving
// and continuous, so stratified u stay stratified on the disc (the lens of camera.glsl); pdf = 1 / pi.
// The same map as concentricDisk in src/scene/camera.cpp.
vec2 sampleConcentricDisk(vec2 u) {
    vec2 s = 2.0 * u - 1.0;
    if (s.x == 0.0 && s.y == 0.0) return vec2(0.0);
    float r, phi;
    if (abs(s.x) > abs(s.y)) {
        r = s.x;
        phi = 0.25 * PI * (s.y / s.x);
    } else {
        r = s.y;
        phi = 0.5 * PI - 0.25 * PI * (s.x / s.y);
    }
    return r * vec2(cos(phi), sin(phi));
}

// Uniform barycentrics (b1, b2) on a triangle, pdf = 1 / area (the square-root map, pbrt-v3 13.6.5).
vec2 sampleTriangle(vec2 u) {
    float su = sqrt(u.x);
    return vec2(1.0 - su, u.y * su);
}

// Solid angle of the triangle with unit corner directions a, b, c seen from their origin (Van Oosterom
// & Strackee 1983, "The solid angle of a plane triangle", eq. 8): atan2 keeps it right beyond pi.
float sphericalTriangleArea(vec3 a, vec3 b, vec3 c) {
    return 2.0 * atan(abs(dot(a, cross(b, c))), 1.0 + dot(a, b) + dot(b, c) + dot(c, a));
}

// A direction uniform in solid angle over the spherical triangle with unit corners A, B, C (Arvo 1995,
// "Stratified sampling of spherical triangles", fig. 2): u.x picks the area of a sub-triangle A B C'
// (C' on the arc from A to C), u.y a point on the arc from B to C'. Continuous and area-preserving, so a
// stratified u stays stratified over the emitter as seen from the shading point.
vec3 sampleSphericalTriangle(vec3 A, vec3 B, vec3 C, vec2 u) {
    vec3 nAB = normalize(cross(A, B)), nBC = normalize(cross(B, C)), nCA = normalize(cross(C, A));
    float alpha = acos(clamp(-dot(nAB, nCA), -1.0, 1.0));  // the interior angles at A, B, C
    float beta = acos(clamp(-dot(nBC, nAB), -1.0, 1.0));
    float gamma = acos(clamp(-dot(nCA, nBC), -1.0, 1.0));
    float subArea = u.x * (alpha + beta + gamma - PI);
    float s = sin(subArea - alpha), t = cos(subArea - alpha);
    float cosAlpha = cos(alpha), sinAlpha = sin(alpha);
    float p = t - cosAlpha, r = s + sinAlpha * dot(A, B);
    float denominator = (r * s + p * t) * sinAlpha;
    float q = denominator != 0.0 ? clamp(((r * t - p * s) * cosAlpha - r) / denominator, -1.0, 1.0) : 1.0;
    vec3 towardC = C - dot(C, A) * A;
    vec3 Cp = q * A + sqrt(max(0.0, 1.0 - q * q)) * (dot(towardC, towardC) > 0.0 ? normalize(towardC) : vec3(0.0));
    float z = clamp(1.0 - u.y * (1.0 - dot(Cp, B)), -1.0, 1.0);
    vec3 towardCp = Cp - dot(Cp, B) * B;
    if (dot(towardCp, towardCp) <= 0.0) return B;
    return z * B + sqrt(max(0.0, 1.0 - z * z)) * normalize(towardCp);
}

// Power heuristic with beta = 2: Veach 1997, eq. 9.13, one sample from each strategy.
float powerHeuristic(float pdfA, float pdfB) {
    float a = pdfA * pdfA, b = pdfB * pdfB;
    return a / (a + b);
}
