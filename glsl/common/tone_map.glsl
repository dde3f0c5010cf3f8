// Display transform, mirroring src/image/tone_map.h (the PNG writer) so that the window shows what a
// PNG would: exposure in stops, a tone curve, then the sRGB transfer function (IEC 61966-2-1).
#define TONE_MAP_CLAMP 0
#define TONE_MAP_REINHARD 1
#define TONE_MAP_ACES 2

float toneCurve(float x, int toneMap) {
    if (toneMap == TONE_MAP_REINHARD) return x / (1.0 + x);
    if (toneMap == TONE_MAP_ACES) {
        // Narkowicz's fit of the ACES filmic curve (2016); the input is capped so it cannot overflow.
        x = min(x, 16.0);
        return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
    }
    return x;
}

float srgbEncode(float linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

vec3 displayEncode(vec3 linear, float exposure, int toneMap) {
    vec3 exposed = linear * exp2(exposure);
    vec3 encoded;
    for (int c = 0; c < 3; ++c) {
        float x = exposed[c];
        encoded[c] = x > 0.0 ? srgbEncode(clamp(toneCurve(x, toneMap), 0.0, 1.0)) : 0.0;
    }
    return encoded;
}

// A heat map for counts (nodes visited, triangles tested, bounces): t in [0, 1] runs through black,
// blue, green, yellow and red to white.
vec3 heatMap(float t) {
    const vec3 stops[6] = vec3[6](vec3(0.0), vec3(0.0, 0.2, 1.0), vec3(0.0, 0.8, 0.3), vec3(1.0, 0.9, 0.0),
                                  vec3(1.0, 0.1, 0.0), vec3(1.0));
    float x = clamp(t, 0.0, 1.0) * 5.0;
    int i = min(int(x), 4);
    return mix(stops[i], stops[i + 1], x - float(i));
}
