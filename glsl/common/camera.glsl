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
