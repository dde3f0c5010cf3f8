// The last denoising pass: multiplies back the albedo that prepare.frag.glsl divided out, and writes
// (radiance, 1), which the display pass shows like an accumulation of one sample.
uniform sampler2D uColor;   // the filtered colour
uniform sampler2D uAlbedo;  // (albedo divided out, pixel class)

out vec4 outResult;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    outResult = vec4(texelFetch(uColor, p, 0).rgb * texelFetch(uAlbedo, p, 0).rgb, 1.0);
}
