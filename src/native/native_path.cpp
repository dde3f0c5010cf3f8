#include "native/native_path.h"

#include <algorithm>
#include <cmath>

#include "core/clock.h"
#include "core/error.h"
#include "native/native_trace.h"

namespace fp::native {

namespace {

constexpr float kPi = 3.14159265358979324f;

// glsl/common/rng.glsl: counter-based. Number i of sample k at pixel p hashes the key
// (p.x | p.y << 16, k, seed, i) with pcg4d, a bijection of four 32-bit words (Jarzynski & Olano 2020,
// "Hash Functions for GPU Rendering", JCGT 9(3)), so distinct keys never share a number.
// glsl/common/rng.glsl: the lens's numbers come from their own place in the stream.
constexpr uint32_t kLensPair = 0x40000000u;

struct Rng {
    // pcg4d's first step, v * 1664525 + 1013904223, done once for the three words that stay fixed.
    uint32_t x, y, z, counter = 0;
    Rng(uint32_t seed, uint32_t px, uint32_t py, uint32_t sample)
        : x((px | (py << 16u)) * 1664525u + 1013904223u),
          y(sample * 1664525u + 1013904223u),
          z(seed * 1664525u + 1013904223u) {}
    // rng.glsl rand2(): the first two words of the hash of the next counter, as floats in [0, 1).
    // Scalar, of only what those words need (the second round's z and w feed nothing that is kept):
    // vectorised, the hash spilled to the stack and cost a third of the reference's speed on the
    // Cornell box.
    glm::vec2 next2() {
        uint32_t a = x, b = y, c = z, w = counter++ * 1664525u + 1013904223u;
        a += b * w;
        b += c * a;
        c += a * b;
        w += b * c;
        a ^= a >> 16u;
        b ^= b >> 16u;
        c ^= c >> 16u;
        w ^= w >> 16u;
        a += b * w;
        b += c * a;
        return glm::vec2(float(a >> 8u), float(b >> 8u)) * (1.0f / 16777216.0f);
    }
};

// glsl/common/sampling.glsl
void orthonormalBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float c = n.x * n.y * a;
    t = {1.0f + s * n.x * n.x * a, s * c, -s * n.x};
    b = {c, s + n.y * n.y * a, -n.y};
}

float powerHeuristic(float pdfA, float pdfB) {
    float a = pdfA * pdfA, b = pdfB * pdfB;
    return a / (a + b);
}

struct Surface {
    glm::vec3 position, geometricNormal, shadingNormal, tangent, bitangent;
    float offset;  // how far rays leaving it start off the surface (surfaceOffset)
    uint32_t material;
    bool frontFace;
    glm::vec3 toLocal(const glm::vec3& v) const {
        return {glm::dot(v, tangent), glm::dot(v, bitangent), glm::dot(v, shadingNormal)};
    }
    glm::vec3 toWorld(const glm::vec3& v) const {
        return v.x * tangent + v.y * bitangent + v.z * shadingNormal;
    }
    bool sameSide(const glm::vec3& local, const glm::vec3& world) const {
        return (local.z > 0.0f) == (glm::dot(world, geometricNormal) > 0.0f);
    }
};

struct LightSample {
    glm::vec3 dir{0.0f, 0.0f, 1.0f};
    float dist = 0.0f;
    glm::vec3 radiance{0.0f};
    float pdf = 0.0f;
    glm::vec3 point{0.0f}, normal{0.0f};  // on an emitter: the point, its emitting side's unit normal
    float offset = 0.0f;                  // and its offset
};

// glsl/common/ray_offset.glsl surfaceOffset(): a hit point computed from its barycentrics errs by a
// few ulps of the triangle's largest vertex coordinate, so rays leave 2^-18 of it (about 30 ulps) off
// the surface (Wachter & Binder 2019, "A Fast and Robust Method for Avoiding Self-Intersection", Ray
// Tracing Gems ch. 6; pbrt-v4 sec. 6.8.6). Independent of the scene's size and of the ray's length.
float surfaceOffset(const Tri& tri) {
    glm::vec3 m = glm::abs(tri.v0) + glm::max(glm::abs(tri.e1), glm::abs(tri.e2));
    return (1.0f / 262144.0f) * std::max(m.x, std::max(m.y, m.z));
}

// ray_offset.glsl offsetToward(): p moved `offset` along unit n, to the side `toward` points to.
glm::vec3 offsetToward(const glm::vec3& p, const glm::vec3& n, float offset, const glm::vec3& toward) {
    return p + (glm::dot(toward, n) >= 0.0f ? offset : -offset) * n;
}

// lights.glsl emitterAreaPdf(): the pick probability over the area from the stored edges, the one
// number both sampleLight and lightPdf use.
float emitterAreaPdf(const Tri& tri) {
    return tri.lightPmf / (0.5f * glm::length(glm::cross(tri.e1, tri.e2)));
}

// sampling.glsl sphericalTriangleArea(): Van Oosterom & Strackee 1983, eq. 8.
float sphericalTriangleArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return 2.0f * std::atan2(std::abs(glm::dot(a, glm::cross(b, c))),
                             1.0f + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
}

// sampling.glsl sampleSphericalTriangle(): Arvo 1995, fig. 2.
glm::vec3 sampleSphericalTriangle(const glm::vec3& A, const glm::vec3& B, const glm::vec3& C, float u0,
                                  float u1) {
    glm::vec3 nAB = glm::normalize(glm::cross(A, B)), nBC = glm::normalize(glm::cross(B, C)),
              nCA = glm::normalize(glm::cross(C, A));
    float alpha = std::acos(glm::clamp(-glm::dot(nAB, nCA), -1.0f, 1.0f));
    float beta = std::acos(glm::clamp(-glm::dot(nBC, nAB), -1.0f, 1.0f));
    float gamma = std::acos(glm::clamp(-glm::dot(nCA, nBC), -1.0f, 1.0f));
    float subArea = u0 * (alpha + beta + gamma - kPi);
    float s = std::sin(subArea - alpha), t = std::cos(subArea - alpha);
    float cosAlpha = std::cos(alpha), sinAlpha = std::sin(alpha);
    float p = t - cosAlpha, r = s + sinAlpha * glm::dot(A, B);
    float denominator = (r * s + p * t) * sinAlpha;
    float q =
        denominator != 0.0f ? glm::clamp(((r * t - p * s) * cosAlpha - r) / denominator, -1.0f, 1.0f) : 1.0f;
    glm::vec3 towardC = C - glm::dot(C, A) * A;
    glm::vec3 Cp =
        q * A + std::sqrt(std::max(0.0f, 1.0f - q * q)) *
                    (glm::dot(towardC, towardC) > 0.0f ? glm::normalize(towardC) : glm::vec3(0.0f));
    float z = glm::clamp(1.0f - u1 * (1.0f - glm::dot(Cp, B)), -1.0f, 1.0f);
    glm::vec3 towardCp = Cp - glm::dot(Cp, B) * B;
    if (glm::dot(towardCp, towardCp) <= 0.0f) return B;
    return z * B + std::sqrt(std::max(0.0f, 1.0f - z * z)) * glm::normalize(towardCp);
}

// lights.glsl sphericalSamplingArea(): the solid angle when the emitter is sampled by it, else 0.
float sphericalSamplingArea(const Scene& scene, const Tri& tri, const glm::vec3& from) {
    constexpr float kMinSphericalArea = 0.1f, kMaxSphericalArea = 6.22f;
    if (!scene.solidAngleLights) return 0.0f;
    glm::vec3 n = glm::cross(tri.e1, tri.e2);
    glm::vec3 c = tri.v0 + (tri.e1 + tri.e2) * (1.0f / 3.0f) - from;
    float facing = -glm::dot(n, c);
    float d2 = glm::dot(c, c);
    if (facing <= 0.0f || facing < 2.0f * kMinSphericalArea * d2 * std::sqrt(d2)) return 0.0f;
    glm::vec3 a = tri.v0 - from;
    float area =
        sphericalTriangleArea(glm::normalize(a), glm::normalize(a + tri.e1), glm::normalize(a + tri.e2));
    return area > 0.0f && area < kMaxSphericalArea ? area : 0.0f;
}

class PathTracer {
  public:
    PathTracer(const Scene& scene, int maxDepth) : scene_(scene), maxDepth_(maxDepth) {
        // lights.glsl environmentSelection(): half of the light samples when there are also emitters.
        environmentSelection_ = scene.environment == glm::vec3(0.0f) ? 0.0f
                                : scene.lights.empty()               ? 1.0f
                                                                     : 0.5f;
    }
    double rays = 0;

    // glsl/integrators/nee.glsl radiance(), for Lambertian materials (MATERIAL_TYPES == 1).
    glm::vec3 radiance(Ray ray, Rng& rng) {
        glm::vec3 L(0.0f), beta(1.0f);
        float lastPdf = 0.0f;
        glm::vec3 lastPosition = ray.origin;
        bool fullWeight = true;
        for (int depth = 0;; ++depth) {
            Hit hit;
            rays += 1;
            if (!traverse(scene_, ray, kInf, false, hit)) {
                glm::vec3 Le = scene_.environment;
                L += beta * Le * (fullWeight ? 1.0f : powerHeuristic(lastPdf, environmentPdf()));
                break;
            }
            Surface s = surfaceAt(ray, hit);
            glm::vec3 Le = s.frontFace ? scene_.emission[s.material] : glm::vec3(0.0f);
            if (Le != glm::vec3(0.0f))
                L += beta * Le *
                     (fullWeight ? 1.0f : powerHeuristic(lastPdf, lightPdf(lastPosition, ray, hit)));
            if (depth == maxDepth_) break;

            // The view direction below the shading normal: f = 0 (nee.glsl, as bdpt.glsl).
            if (s.toLocal(-ray.dir).z <= 0.0f) break;
            const glm::vec3& kd = scene_.diffuse[s.material];
            LightSample ls = sampleLight(s.position, rng);
            glm::vec3 wi = s.toLocal(ls.dir);
            if (ls.pdf > 0.0f && s.sameSide(wi, ls.dir)) {
                glm::vec3 f = wi.z > 0.0f ? kd / kPi * wi.z : glm::vec3(0.0f);
                if (f != glm::vec3(0.0f) && lightVisible(s, ls))
                    L += beta * f * ls.radiance * powerHeuristic(ls.pdf, wi.z > 0.0f ? wi.z / kPi : 0.0f) /
                         ls.pdf;
            }

            // bsdf.glsl bsdfSample() for a Lambertian surface: cosine-weighted (Malley's method), from
            // surface.glsl drawBounceNumbers(): a pair for the direction, a pair for the lobe (unused
            // here) and the roulette.
            glm::vec2 u = rng.next2();
            float roulette = rng.next2().y;
            float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
            glm::vec3 local(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x)));
            if (!(local.z > 0.0f)) break;
            glm::vec3 dir = s.toWorld(local);
            if (!s.sameSide(local, dir)) break;
            beta *= kd;
            lastPdf = local.z / kPi;
            lastPosition = s.position;
            fullWeight = false;
            // surface.glsl survivesRoulette() (pbrt-v4 PathIntegrator::Li).
            if (depth >= 3) {
                float keep = std::min(1.0f, std::max(beta.r, std::max(beta.g, beta.b)));
                if (roulette >= keep) break;
                beta /= keep;
            }
            ray = spawnRay(s, dir);
        }
        return L;
    }

  private:
    // surface.glsl surfaceAt()
    Surface surfaceAt(const Ray& ray, const Hit& hit) const {
        const Tri& tri = scene_.tris[hit.triangle];
        Surface s;
        // From the barycentrics, not ray.origin + t dir, whose error grows with the ray's length.
        s.position = tri.v0 + hit.uv.x * tri.e1 + hit.uv.y * tri.e2;
        s.offset = surfaceOffset(tri);
        glm::vec3 n = glm::normalize(glm::cross(tri.e1, tri.e2));
        s.frontFace = glm::dot(n, ray.dir) < 0.0f;
        s.geometricNormal = s.frontFace ? n : -n;
        const auto& vn = scene_.normals[hit.triangle];
        glm::vec3 ns =
            glm::normalize((1.0f - hit.uv.x - hit.uv.y) * vn[0] + hit.uv.x * vn[1] + hit.uv.y * vn[2]);
        s.shadingNormal = glm::dot(ns, s.geometricNormal) < 0.0f ? -ns : ns;
        orthonormalBasis(s.shadingNormal, s.tangent, s.bitangent);
        s.material = tri.material;
        return s;
    }

    // surface.glsl spawnRay()
    static Ray spawnRay(const Surface& s, const glm::vec3& dir) {
        return {offsetToward(s.position, s.geometricNormal, s.offset, dir), dir};
    }

    // lights.glsl lightVisible() and ray_offset.glsl segmentOccluded(): a shadow ray to an emitter point
    // is offset at both ends and stops exactly at the far end's offset point (no fraction of its length:
    // that is shorter than the offsets when the points are close or far from the origin).
    bool lightVisible(const Surface& s, const LightSample& ls) {
        Hit shadow;
        rays += 1;
        if (ls.dist == kInf) return !traverse(scene_, spawnRay(s, ls.dir), kInf, true, shadow);
        glm::vec3 d = ls.point - s.position;
        glm::vec3 from = offsetToward(s.position, s.geometricNormal, s.offset, d);
        glm::vec3 to = offsetToward(ls.point, ls.normal, ls.offset, -d);
        glm::vec3 e = to - from;
        if (!(glm::dot(e, d) > 0.0f)) return true;  // closer than their offsets: touching surfaces
        float len = glm::length(e);
        return !traverse(scene_, {from, e / len}, len, true, shadow);
    }

    float environmentPdf() const { return environmentSelection_ / (4.0f * kPi); }

    // lights.glsl sampleLight()
    LightSample sampleLight(const glm::vec3& from, Rng& rng) const {
        LightSample ls;
        float pEnvironment = environmentSelection_;
        if (pEnvironment > 0.0f && (pEnvironment >= 1.0f || rng.next2().x < pEnvironment)) {
            glm::vec2 u = rng.next2();
            float z = 1.0f - 2.0f * u.x, phi = 2.0f * kPi * u.y;
            float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
            ls.dir = {r * std::cos(phi), r * std::sin(phi), z};
            ls.dist = kInf;
            ls.radiance = scene_.environment;
            ls.pdf = environmentPdf();
            return ls;
        }
        if (scene_.lights.empty()) return ls;
        // lights.glsl sampleEmitterPoint(): the pick's number, rescaled to the picked entry's share,
        // is the point's first coordinate (exact: the cdf lies on the 2^-24 grid, buildScene).
        glm::vec2 u = rng.next2();
        float v = u.x;
        int lo = 0, hi = int(scene_.lights.size()) - 1;
        while (lo < hi) {  // first entry whose cdf exceeds v
            int mid = (lo + hi) / 2;
            if (scene_.lights[mid].cdf <= v)
                lo = mid + 1;
            else
                hi = mid;
        }
        const Tri& tri = scene_.tris[scene_.lights[lo].triangle];
        float below = lo > 0 ? scene_.lights[size_t(lo) - 1].cdf : 0.0f;
        float b0, b1 = u.y;
        if (tri.lightPmf >= 1.0f / 4096.0f) {
            b0 = (v - below) / tri.lightPmf;
        } else {  // a pair of its own
            glm::vec2 w = rng.next2();
            b0 = w.x;
            b1 = w.y;
        }
        ls.normal = glm::normalize(glm::cross(tri.e1, tri.e2));
        ls.offset = surfaceOffset(tri);
        float solidAngle = sphericalSamplingArea(scene_, tri, from);
        if (solidAngle > 0.0f) {
            glm::vec3 a = tri.v0 - from;
            ls.dir = sampleSphericalTriangle(glm::normalize(a), glm::normalize(a + tri.e1),
                                             glm::normalize(a + tri.e2), b0, b1);
            float cosLight = -glm::dot(ls.normal, ls.dir);
            if (cosLight <= 0.0f) return ls;
            ls.dist = -glm::dot(a, ls.normal) / cosLight;
            ls.point = from + ls.dist * ls.dir;
            ls.radiance = scene_.emission[tri.material];
            ls.pdf = (1.0f - environmentSelection_) * tri.lightPmf / solidAngle;
            return ls;
        }
        float su = std::sqrt(b0);  // uniform on the triangle: sampling.glsl sampleTriangle()
        ls.point = tri.v0 + (1.0f - su) * tri.e1 + b1 * su * tri.e2;
        glm::vec3 toLight = ls.point - from;
        float dist2 = glm::dot(toLight, toLight);
        ls.dist = std::sqrt(dist2);
        ls.dir = toLight / ls.dist;
        float cosLight = -glm::dot(ls.normal, ls.dir);
        if (cosLight <= 0.0f || dist2 == 0.0f) return ls;
        ls.radiance = scene_.emission[tri.material];
        ls.pdf = (1.0f - environmentSelection_) * emitterAreaPdf(tri) * dist2 / cosLight;
        return ls;
    }

    // lights.glsl lightPdf()
    float lightPdf(const glm::vec3& from, const Ray& ray, const Hit& hit) const {
        const Tri& tri = scene_.tris[hit.triangle];
        float solidAngle = sphericalSamplingArea(scene_, tri, from);
        if (solidAngle > 0.0f) return (1.0f - environmentSelection_) * tri.lightPmf / solidAngle;
        float cosLight = std::abs(glm::dot(glm::normalize(glm::cross(tri.e1, tri.e2)), ray.dir));
        return (1.0f - environmentSelection_) * emitterAreaPdf(tri) * hit.t * hit.t / cosLight;
    }

    const Scene& scene_;
    int maxDepth_;
    float environmentSelection_ = 0.0f;
};

}  // namespace

Result render(const Scene& scene, const Camera& camera, const Settings& settings) {
    if (settings.width < 1 || settings.height < 1 || settings.spp < 1 || settings.maxDepth < 0)
        throw Error("native reference: size, spp and max depth must be positive");
    Result out;
    out.width = settings.width;
    out.height = settings.height;
    out.sum.assign(size_t(settings.width) * settings.height, glm::vec4(0.0f));
    out.squares = out.sum;

    // glsl/common/camera.glsl with the basis Renderer::draw computes.
    const CameraFrame frame = cameraFrame(camera, float(settings.width) / float(settings.height));
    const glm::vec3 rightUnit = glm::normalize(frame.right), upUnit = glm::normalize(frame.up);
    glm::vec2 resolution(settings.width, settings.height);

    PathTracer tracer(scene, settings.maxDepth);
    double cpuStart = threadCpuSeconds();
    for (int y = 0; y < settings.height; ++y)  // y counts from the bottom, as gl_FragCoord does
        for (int x = 0; x < settings.width; ++x) {
            size_t index = size_t(settings.height - 1 - y) * settings.width + x;
            for (int i = 0; i < settings.spp; ++i) {
                Rng rng(settings.seed, uint32_t(x), uint32_t(y), settings.sampleOffset + uint32_t(i));
                glm::vec2 ndc = 2.0f * (glm::vec2(x, y) + rng.next2()) / resolution - 1.0f;
                glm::vec3 pinhole = frame.forward + ndc.x * frame.right + ndc.y * frame.up;
                Ray ray{frame.eye, glm::normalize(pinhole)};
                if (frame.lensRadius > 0.0f) {
                    // The thin lens of camera.glsl (pbrt-v4 5.2.3): from a point of the lens toward where
                    // the pinhole ray meets the plane of focus. Its numbers are the shader's: counters
                    // kLensPair and the next (rng.glsl, randAt), out of the stream's order.
                    uint32_t counter = rng.counter;
                    rng.counter = kLensPair;
                    glm::vec2 lens = rng.next2();
                    rng.counter = counter;
                    glm::vec2 d = frame.lensRadius * concentricDisk(lens);
                    glm::vec3 origin = frame.eye + d.x * rightUnit + d.y * upUnit;
                    ray = Ray{origin, glm::normalize(frame.eye + frame.focusDistance * pinhole - origin)};
                }
                glm::vec3 c = tracer.radiance(ray, rng);
                if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) c = glm::vec3(0.0f);
                out.sum[index] += glm::vec4(c, 1.0f);
                out.squares[index] += glm::vec4(c * c, 0.0f);
            }
        }
    out.cpuSeconds = threadCpuSeconds() - cpuStart;
    out.paths = double(settings.width) * settings.height * settings.spp;
    out.rays = tracer.rays;
    return out;
}

}  // namespace fp::native
