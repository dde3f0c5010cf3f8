// The splat pass's fragment: the point's record, added to the light image by blending (ONE, ONE).
flat in vec4 vSum;
flat in vec4 vSquares;

layout(location = 0) out vec4 outSum;      // (sum of contributions, rays traced by paths launched here)
layout(location = 1) out vec4 outSquares;  // (sum of squared contributions, contributions dropped)

void main() {
    outSum = vSum;
    outSquares = vSquares;
}
