// A ray, and what it hits (common/intersect.glsl traces one).
struct Ray {
    vec3 origin;
    vec3 dir;
};

struct Hit {
    float t;
    int triangle;  // -1: nothing hit
    vec2 uv;       // barycentrics of v1 and v2
    int instance;  // the first node of the instance's transform pair (pack/layout.h), -1: world triangle
};
