// Colour textures (MTL map_Kd), compiled in only when the scene has some (SURFACE_TEXTURES), so that
// other scenes pay nothing. The layout is in src/pack/layout.h: three texture coordinates per triangle,
// every texture's sRGB-encoded texels in one RGBA8 buffer, and (first texel, width, height) per texture.
#ifdef SURFACE_TEXTURES
// Read as images or texel fetches like the scene buffers (scene_data.glsl), except the RGBA8 texels,
// whose texelFetch llvmpipe already generates inline.
#ifdef SCENE_READS_IMAGES
layout(rg32f) readonly uniform imageBuffer uTexcoords;
layout(rgba32i) readonly uniform iimageBuffer uTextureTable;
#else
uniform samplerBuffer uTexcoords;
uniform isamplerBuffer uTextureTable;
#endif
uniform samplerBuffer uTextureTexels;

vec2 texcoordTexel(int i) { return SCENE_TEXEL(uTexcoords, i).xy; }
ivec4 textureTableTexel(int t) { return SCENE_TEXEL(uTextureTable, t); }

int materialTexture(int m) { return int(materialTexel(m * MATERIAL_TEXELS + 4).x); }

// The texture coordinates at barycentrics b of triangle i.
vec2 fetchTexcoord(int i, vec2 b) {
    vec2 t0 = texcoordTexel(i * TEXCOORD_TEXELS);
    vec2 t1 = texcoordTexel(i * TEXCOORD_TEXELS + 1);
    vec2 t2 = texcoordTexel(i * TEXCOORD_TEXELS + 2);
    return (1.0 - b.x - b.y) * t0 + b.x * t1 + b.y * t2;
}

// The exact sRGB decoding curve (IEC 61966-2-1:1999), as srgbDecode in src/image/tone_map.h.
vec3 srgbDecode(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

// The linear colour of texel xy (integer-valued, any range) of a texture, wrapped around (repeat). The
// floor-modulo is done in float, exact for integers below 2^24 (GLSL leaves % of negatives undefined);
// the clamp only guards against a rounded division.
vec3 textureTexel(ivec4 info, vec2 xy) {
    vec2 size = vec2(info.yz);
    ivec2 p = clamp(ivec2(xy - size * floor(xy / size)), ivec2(0), info.yz - 1);
    return srgbDecode(texelFetch(uTextureTexels, info.x + p.y * info.y + p.x).rgb);
}

// Bilinear filtering of texture t at uv, texel centres at half-integers, with repeat wrapping. Rows are
// stored top first and OBJ's v = 0 is the bottom of the image. Texels are decoded before filtering, as
// GPUs filter sRGB textures.
vec3 sampleTexture(int t, vec2 uv) {
    ivec4 info = textureTableTexel(t);
    vec2 xy = vec2(uv.x, 1.0 - uv.y) * vec2(info.yz) - 0.5;
    vec2 base = floor(xy), f = xy - base;
    vec3 top = mix(textureTexel(info, base), textureTexel(info, base + vec2(1.0, 0.0)), f.x);
    vec3 bottom = mix(textureTexel(info, base + vec2(0.0, 1.0)), textureTexel(info, base + vec2(1.0)), f.x);
    return mix(top, bottom, f.y);
}

// Material m's Kd at barycentrics b of triangle i: `diffuse` times its texture, if it has one.
vec3 texturedDiffuse(int m, vec3 diffuse, int i, vec2 b) {
    int t = materialTexture(m);
    return t < 0 ? diffuse : diffuse * sampleTexture(t, fetchTexcoord(i, b));
}
#endif
