// Reading the scene from its buffer textures. The texel layout is documented once, in src/gpu/layout.h;
// the *_TEXELS constants come from there as defines.
uniform samplerBuffer uTriangles;
uniform samplerBuffer uNormals;
uniform usamplerBuffer uNodes;  // RGBA32UI, NODE_TEXELS per node
uniform samplerBuffer uMaterials;
uniform samplerBuffer uLights;
uniform int uLightCount;

struct TriangleData {
    vec3 v0, e1, e2;  // e1 = v1 - v0, e2 = v2 - v0
    int material;
    float lightPmf;   // probability that light sampling picks this triangle
};

TriangleData fetchTriangle(int i) {
    vec4 a = texelFetch(uTriangles, i * TRIANGLE_TEXELS);
    vec4 b = texelFetch(uTriangles, i * TRIANGLE_TEXELS + 1);
    vec4 c = texelFetch(uTriangles, i * TRIANGLE_TEXELS + 2);
    return TriangleData(a.xyz, b.xyz, c.xyz, int(a.w), b.w);
}

vec3 fetchShadingNormal(int i, vec2 uv) {
    vec3 n0 = texelFetch(uNormals, i * NORMAL_TEXELS).xyz;
    vec3 n1 = texelFetch(uNormals, i * NORMAL_TEXELS + 1).xyz;
    vec3 n2 = texelFetch(uNormals, i * NORMAL_TEXELS + 2).xyz;
    return normalize((1.0 - uv.x - uv.y) * n0 + uv.x * n1 + uv.y * n2);
}

vec3 materialEmission(int m) { return texelFetch(uMaterials, m * MATERIAL_TEXELS + 1).rgb; }

#include "common/luminance.glsl"
