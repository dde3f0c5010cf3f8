// The splat pass: one point per light-tracing record (light_trace.frag.glsl), drawn with additive
// blending into the light image at the pixel the record names. The records drawn are uFirstRecord ..
// LIGHT_RECORDS of each launched path (the earlier ones are empty in nee's light pass);
// vertex k of path j reads record uFirstRecord + k of slot j (light_launch.glsl); the last record of
// each path (its statistics) goes to the path's own pixel. A record that lands nowhere, or a slot past
// the region's end, is put outside the clip volume, so it makes no fragment.
uniform sampler2DArray uRecords;  // one layer per record
#include "passes/light_launch.glsl"
uniform int uFirstRecord;

flat out vec4 vSum;      // (contribution, rays traced)
flat out vec4 vSquares;  // (squared contribution, contributions dropped)

void main() {
    int drawn = LIGHT_RECORDS + 1 - uFirstRecord;
    int k = uFirstRecord + gl_VertexID % drawn, path = gl_VertexID / drawn;
    int perRow = launchSlotsPerRow(), slot = path % perRow, row = path / perRow;
    ivec2 source;  // the path's pixel
    ivec2 size = textureSize(uRecords, 0).xy;
    if (!launchPixel(slot, row, source)) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec4 r = texelFetch(uRecords, ivec3(slot, row, k), 0);
    int target;
    if (k < LIGHT_RECORDS) {
        target = int(r.a);
        vSum = vec4(r.rgb, 0.0);
        vSquares = vec4(r.rgb * r.rgb, 0.0);
    } else {
        target = r.x != 0.0 || r.y != 0.0 ? source.y * size.x + source.x : -1;
        vSum = vec4(0.0, 0.0, 0.0, r.x);
        vSquares = vec4(0.0, 0.0, 0.0, r.y);
    }
    if (target < 0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec2 pixel = vec2(target % size.x, target / size.x) + 0.5;
    gl_Position = vec4(pixel / vec2(size) * 2.0 - 1.0, 0.0, 1.0);
}
