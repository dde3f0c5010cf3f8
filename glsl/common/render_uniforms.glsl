// The render's settings that the tracing passes (passes/trace.frag.glsl, passes/light_trace.frag.glsl)
// and the integrators read (src/render/renderer.cpp, setTraceUniforms).
uniform int uMaxDepth;
uniform uint uSeed;
