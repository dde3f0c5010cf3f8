// Which pixels launch light paths, shared by the light-tracing pass (light_trace.frag.glsl) and the
// splat pass (light_splat.vert.glsl). The launch region's launching pixels are listed row by row, a row
// holding launchSlotsPerRow() slots, and the trace pass shades one fragment per slot in the rectangle of
// slots (its lower-left corner at the origin of the records), so that no fragment is spent on a pixel
// that does not launch.
// bdpt (stride 1): every pixel launches. nee's light pass (stride K): the 4 x 4 blocks whose column + row
// + sample is a multiple of K, a diagonal pattern that moves on with the sample; whole blocks, because
// llvmpipe shades a block's fragments together. Every pixel's light paths are alike (only their random
// streams differ), so which ones launch does not matter: each launched path's contributions count
// (region pixels / launching pixels) times (uLaunchWeight), and the light image's expectation per
// sample is the same as when every pixel launches (its N stays the samples per pixel).
uniform ivec2 uLaunchOrigin;  // the launch region's lower-left pixel
uniform int uLaunchWidth;
uniform int uLaunchStride;
uniform uint uLightSample;  // the sample index (sample offset included) whose light paths are traced

// As LightSplat::slotsPerRow (src/render/light_splat.cpp): 4 slots per launching block a row can meet.
int launchSlotsPerRow() {
    if (uLaunchStride == 1) return uLaunchWidth;
    int blocks = ((uLaunchOrigin.x + uLaunchWidth - 1) >> 2) - (uLaunchOrigin.x >> 2) + 1;
    return 4 * ((blocks + uLaunchStride - 1) / uLaunchStride);
}

// The pixel of slot `slot` of row `row`; false for a slot past the region's end (or before its start).
bool launchPixel(int slot, int row, out ivec2 pixel) {
    int y = uLaunchOrigin.y + row;
    if (uLaunchStride == 1) {
        pixel = ivec2(uLaunchOrigin.x + slot, y);
        return slot < uLaunchWidth;
    }
    int phase = int(uLightSample % uint(uLaunchStride));
    int wanted = (uLaunchStride - ((y >> 2) + phase) % uLaunchStride) % uLaunchStride;  // block columns
    int firstBlock = uLaunchOrigin.x >> 2;
    firstBlock += (wanted - firstBlock % uLaunchStride + uLaunchStride) % uLaunchStride;
    pixel = ivec2(4 * (firstBlock + uLaunchStride * (slot >> 2)) + (slot & 3), y);
    return pixel.x >= uLaunchOrigin.x && pixel.x < uLaunchOrigin.x + uLaunchWidth;
}
