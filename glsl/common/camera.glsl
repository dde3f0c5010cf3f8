// A pinhole camera: uCameraRight and uCameraUp are scaled by tan(fov/2) (and the aspect ratio),
// so a point of the image plane at normalised device coordinates (x, y) lies at forward + x*right + y*up.
uniform vec3 uCameraEye;
uniform vec3 uCameraForward;
uniform vec3 uCameraRight;
uniform vec3 uCameraUp;
uniform vec2 uResolution;

// `pixel` is a continuous position in pixels, y up (gl_FragCoord convention).
Ray cameraRay(vec2 pixel) {
    vec2 ndc = 2.0 * pixel / uResolution - 1.0;
    return Ray(uCameraEye, normalize(uCameraForward + ndc.x * uCameraRight + ndc.y * uCameraUp));
}

// Whether a ray is one of cameraRay's: only they start at the pinhole itself (every other ray leaves a
// surface point). Single-sided surfaces hide their backs from these alone (opacity.glsl).
bool isCameraRay(Ray ray) { return ray.origin == uCameraEye; }

// The pinhole as a sensor, for light tracing (pbrt-v3 16.1.1; Veach 1997, ch. 10). cameraRay spreads
// directions uniformly over the image plane at distance 1, of area A = 4 |right| |up|; a direction at
// angle theta to the forward axis then has solid-angle density p(w) = 1 / (A cos^3 theta) (pbrt-v3 eq.
// 16.2: dA = dw / cos^3 theta on that plane), and the importance normalised over the whole film is
// We = 1 / (A cos^4 theta) (eq. 16.3). One light-traced contribution to pixel j is then
// We G f ... / p, and the pixel's value is the sum of those over N light paths per pixel, divided by
// N (the film has W H pixels, each 1 / (W H) of We's domain).
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
