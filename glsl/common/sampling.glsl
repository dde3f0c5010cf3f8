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

// Cosine-weighted around +z, the normal of the local shading frame (Malley's method: uniform on the
// disk, projected up); pdf = cos(theta) / pi (pbrt-v4 A.5.3).
vec3 sampleCosineLocal(vec2 u) {
    float r = sqrt(u.x);
    float phi = 2.0 * PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
}

// Uniform barycentrics (b1, b2) on a triangle, pdf = 1 / area (the square-root map, pbrt-v3 13.6.5).
vec2 sampleTriangle(vec2 u) {
    float su = sqrt(u.x);
    return vec2(1.0 - su, u.y * su);
}

// Power heuristic with beta = 2: Veach 1997, eq. 9.13, one sample from each strategy.
float powerHeuristic(float pdfA, float pdfB) {
    float a = pdfA * pdfA, b = pdfB * pdfB;
    return a / (a + b);
}
