// Reading the scene from its buffer textures. The texel layout is documented once, in src/pack/layout.h;
// the *_TEXELS constants come from there as defines.
//
// Every read of these buffers goes through the one-line helpers below (triangleTexel ... lightTexel), and
// so do the optional textures' (texcoordTexel, textureTableTexel in textures.glsl; environmentMapTexel,
// environmentCdfTexel in lights.glsl), through SCENE_TEXEL and SCENE_TEXEL_2D. With SCENE_READS_IMAGES
// (the context has GL_ARB_shader_image_load_store: gpu/scene_textures.h), they are imageLoads of
// read-only images, which llvmpipe generates inline; without, texelFetches, which llvmpipe makes
// out-of-line calls for these formats, spilling everything live (docs/optimisation-log.md, entries 18 and
// 23). The texels are the same, so the images rendered are bit-identical. Each image uses the image unit
// of its texture unit's number (the uniforms keep their names); layout::kImageUnits lists them.
#ifdef SCENE_READS_IMAGES
layout(rgba32f) readonly uniform imageBuffer uTriangles;
layout(rgba32f) readonly uniform imageBuffer uNormals;
layout(rgba32ui) readonly uniform uimageBuffer uNodes;  // NODE_TEXELS per node
layout(rgba32f) readonly uniform imageBuffer uMaterials;
layout(rgba32f) readonly uniform imageBuffer uLights;
#define SCENE_TEXEL(buffer, i) imageLoad(buffer, i)
#define SCENE_TEXEL_2D(texture, p) imageLoad(texture, p)
#else
uniform samplerBuffer uTriangles;
uniform samplerBuffer uNormals;
uniform usamplerBuffer uNodes;  // RGBA32UI, NODE_TEXELS per node
uniform samplerBuffer uMaterials;
uniform samplerBuffer uLights;
#define SCENE_TEXEL(buffer, i) texelFetch(buffer, i)
#define SCENE_TEXEL_2D(texture, p) texelFetch(texture, p, 0)
#endif
uniform int uLightCount;

vec4 triangleTexel(int i) { return SCENE_TEXEL(uTriangles, i); }
vec4 normalTexel(int i) { return SCENE_TEXEL(uNormals, i); }
uvec4 nodeTexel(int i) { return SCENE_TEXEL(uNodes, i); }
vec4 materialTexel(int i) { return SCENE_TEXEL(uMaterials, i); }
vec4 lightTexel(int i) { return SCENE_TEXEL(uLights, i); }

struct TriangleData {
    vec3 v0, e1, e2;  // e1 = v1 - v0, e2 = v2 - v0
    int material;
    float lightPmf;   // probability that light sampling picks this triangle
    float flags;      // TRIANGLE_ALPHA_FLAG + TRIANGLE_SINGLE_SIDED_FLAG (opacity.glsl)
};

TriangleData fetchTriangle(int i) {
    vec4 a = triangleTexel(i * TRIANGLE_TEXELS);
    vec4 b = triangleTexel(i * TRIANGLE_TEXELS + 1);
    vec4 c = triangleTexel(i * TRIANGLE_TEXELS + 2);
    return TriangleData(a.xyz, b.xyz, c.xyz, int(a.w), b.w, c.w);
}

vec3 fetchShadingNormal(int i, vec2 uv) {
    vec3 n0 = normalTexel(i * NORMAL_TEXELS).xyz;
    vec3 n1 = normalTexel(i * NORMAL_TEXELS + 1).xyz;
    vec3 n2 = normalTexel(i * NORMAL_TEXELS + 2).xyz;
    return normalize((1.0 - uv.x - uv.y) * n0 + uv.x * n1 + uv.y * n2);
}

vec3 materialEmission(int m) { return materialTexel(m * MATERIAL_TEXELS + 1).rgb; }

#include "common/luminance.glsl"

#ifdef INSTANCE_NODES_START
// Point or direction (w = 0) p through the 3 x 4 transform whose rows start at node texel `base` (an
// instance's node pair, pack/layout.h).
vec3 transformRows(int base, vec3 p, float w) {
    vec4 r0 = uintBitsToFloat(nodeTexel(base)), r1 = uintBitsToFloat(nodeTexel(base + 1)),
         r2 = uintBitsToFloat(nodeTexel(base + 2));
    return vec3(dot(r0.xyz, p) + w * r0.w, dot(r1.xyz, p) + w * r1.w, dot(r2.xyz, p) + w * r2.w);
}

// The hit being shaded's instance (surface.glsl placeInInstance): gInstanceLinear takes its tangents to
// the world, gInstanceNormals (the inverse transpose) its normals.
mat3 gInstanceLinear = mat3(1.0);
mat3 gInstanceNormals = mat3(1.0);
#endif
