// A perspective camera (src/scene/scene.h, Camera): a pinhole at uCameraEye, or with uLensRadius > 0 a
// thin lens, a disc of that radius around the eye perpendicular to uCameraForward. uCameraRight and
// uCameraUp are scaled by tan(fov/2) (and the aspect ratio), so a point of the image plane at normalised
// device coordinates (x, y) lies at forward + x*right + y*up, at depth 1 along forward.
#include "common/ray.glsl"
#include "common/rng.glsl"
#include "common/sampling.glsl"
uniform vec3 uCameraEye;
uniform vec3 uCameraForward;
uniform vec3 uCameraRight;
uniform vec3 uCameraUp;
uniform vec2 uResolution;
uniform float uLensRadius;     // half the aperture; 0: a pinhole
uniform float uFocusDistance;  // from the eye to the plane in focus, along uCameraForward

// The ray through the pinhole (or the lens's centre). `pixel` is a continuous position in pixels, y up
// (gl_FragCoord convention).
Ray cameraRay(vec2 pixel) {
    vec2 ndc = 2.0 * pixel / uResolution - 1.0;
    return Ray(uCameraEye, normalize(uCameraForward + ndc.x * uCameraRight + ndc.y * uCameraUp));
}

// The point of the lens for u in [0, 1)^2, uniform by area (density 1 / (pi r^2)) over the disc.
vec3 lensPoint(vec2 u) {
    vec2 d = uLensRadius * sampleConcentricDisk(u);
    return uCameraEye + d.x * normalize(uCameraRight) + d.y * normalize(uCameraUp);
}

// The thin lens (Cook et al. 1984, "Distributed ray tracing"; Kolb et al. 1995; pbrt-v4 5.2.3): every
// ray from one film point through the lens crosses the plane of focus where the ray through the lens's
// centre does, at eye + f (forward + x right + y up) (depth f along forward). So a point at depth f is
// sharp, and one at depth d spreads over a disc of radius r |d - f| / d on the plane of focus.
Ray cameraLensRay(vec2 pixel, vec2 u) {
    vec2 ndc = 2.0 * pixel / uResolution - 1.0;
    vec3 focus = uCameraEye + uFocusDistance * (uCameraForward + ndc.x * uCameraRight + ndc.y * uCameraUp);
    vec3 origin = lensPoint(u);
    return Ray(origin, normalize(focus - origin));
}

// The camera ray of the sample being traced: through the pinhole, or through a point of the lens drawn
// from the lens's own pair of the random stream (rng.glsl, kLensPair). A pinhole draws no number for it,
// so its images are bit for bit those of the camera before the lens existed.
// It records the ray's origin (the eye or the lens point) for isCameraRay.
vec3 gCameraRayOrigin = vec3(0.0);
Ray primaryRay(vec2 pixel) {
    Ray ray = uLensRadius > 0.0 ? cameraLensRay(pixel, randAt(kLensPair)) : cameraRay(pixel);
    gCameraRayOrigin = ray.origin;
    return ray;
}

// Whether a ray is the camera ray primaryRay made: only it starts at that point of the lens (every
// other ray leaves a surface point). Single-sided surfaces hide their backs from it alone (opacity.glsl).
bool isCameraRay(Ray ray) { return ray.origin == gCameraRayOrigin; }

// The camera as a sensor, for light tracing (pbrt-v3 16.1.1; Veach 1997, ch. 10). cameraRay spreads
// directions uniformly over the image plane at distance 1, of area A = 4 |right| |up|; a direction at
// angle theta to the forward axis then has solid-angle density p(w) = 1 / (A cos^3 theta) (pbrt-v3 eq.
// 16.2: dA = dw / cos^3 theta on that plane), and the importance normalised over the whole film is
// We = 1 / (A cos^4 theta) (eq. 16.3). One light-traced contribution to pixel j is then
// We G f ... / p, and the pixel's value is the sum of those over N light paths per pixel, divided by
// N (the film has W H pixels, each 1 / (W H) of We's domain).
// A thin lens (pbrt-v4 5.2.3, PerspectiveCamera::We, PDF_We, SampleWi): from any lens point the
// directions through the film still have density 1 / (A cos^3 theta) (the plane of focus at depth f
// is the film scaled by f, and its distance along a direction is f / cos theta), the lens point has
// density 1 / L by area (L = pi r^2), and the importance is We = 1 / (A L cos^4 theta). Light tracing
// picks the lens point by area too, so its contribution We G / (1 / L) loses the L: cameraImportance is
// L We, the same for both cameras, and the lens area cancels out of the estimate and of the MIS weights
// (z0's density is the same for every strategy that uses it).
float cameraDirectionPdf(vec3 dir) {
    float cosTheta = dot(dir, uCameraForward);
    if (cosTheta <= 0.0) return 0.0;
    return 1.0 / (4.0 * length(uCameraRight) * length(uCameraUp) * cosTheta * cosTheta * cosTheta);
}
float cameraImportance(vec3 dir) { return cameraDirectionPdf(dir) / max(dot(dir, uCameraForward), 1e-20); }

// The continuous pixel position (the inverse of cameraRay) where the ray from the eye to p crosses the
// image plane; false if p is behind the eye or projects outside the image.
bool projectToPixel(vec3 p, out vec2 pixel) {
    vec3 d = p - uCameraEye;
    float depth = dot(d, uCameraForward);
    if (depth <= 0.0) return false;
    vec2 ndc = vec2(dot(d, uCameraRight) / dot(uCameraRight, uCameraRight),
                    dot(d, uCameraUp) / dot(uCameraUp, uCameraUp)) / depth;
    pixel = (ndc + 1.0) * 0.5 * uResolution;
    return all(greaterThanEqual(pixel, vec2(0.0))) && all(lessThan(pixel, uResolution));
}

// The inverse of cameraLensRay: the pixel whose rays through lens point `lens` include the one toward
// p, found where that ray crosses the plane of focus (projected from the eye, as the lens's centre
// sees it); false if p is not in front of the lens or lands outside the image. A pinhole (lens: the eye)
// is projectToPixel.
bool projectThroughLens(vec3 lens, vec3 p, out vec2 pixel) {
    if (uLensRadius <= 0.0) return projectToPixel(p, pixel);
    vec3 d = p - lens;
    float depth = dot(d, uCameraForward);
    if (depth <= 0.0) return false;
    return projectToPixel(lens + d * (uFocusDistance / depth), pixel);
}
