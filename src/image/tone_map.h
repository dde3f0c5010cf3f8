#pragma once
// Linear radiance -> display code values: exposure, tone curve, sRGB encoding, 8-bit quantisation.
// Everything here is inline and branch-light on purpose: the GLSL display pass mirrors these functions
// line by line, and the tests compare the two, so keep the order of operations identical in both.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <glm/glm.hpp>

#include "image/image.h"

namespace fp {

// Name <-> enum for the --tone-map flag. parseToneMap accepts exactly "clamp", "reinhard" or "aces"
// and throws fp::Error listing those choices otherwise.
ToneMap parseToneMap(const std::string& name);
const char* toneMapName(ToneMap toneMap);

// The tone curves take one linear channel value x >= 0 (finite) and return a display-linear value;
// the caller clamps the result to [0, 1].

// Identity; values above 1 are clipped by the caller's clamp.
inline float toneMapClamp(float x) {
    return x;
}

// Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", eq. 3, applied per
// channel: x / (1 + x). Needs x > -1; the pipeline only feeds it x >= 0.
inline float toneMapReinhard(float x) {
    return x / (1.0f + x);
}

// Krzysztof Narkowicz, "ACES Filmic Tone Mapping Curve" (blog post, January 2016, commonly cited as
// "Narkowicz 2015"): a rational fit to the ACES RRT+ODT luminance curve, pre-exposed so that 1 maps
// to about 0.8. The fit exceeds 1 for every x above about 7.24 (where 0.08x^2 - 0.56x - 0.14 = 0),
// so capping x at 16 changes nothing after the clamp but keeps x*x from overflowing to inf/inf = NaN.
// The fit is (x (a x + b)) / (x (c x + d) + e) with these coefficients (HDR-FLIP solves it for x).
constexpr float kAcesA = 2.51f, kAcesB = 0.03f, kAcesC = 2.43f, kAcesD = 0.59f, kAcesE = 0.14f;
inline float toneMapAces(float x) {
    x = std::min(x, 16.0f);
    return (x * (kAcesA * x + kAcesB)) / (x * (kAcesC * x + kAcesD) + kAcesE);
}

inline float applyToneMap(float x, ToneMap toneMap) {
    switch (toneMap) {
        case ToneMap::Reinhard:
            return toneMapReinhard(x);
        case ToneMap::Aces:
            return toneMapAces(x);
        case ToneMap::Clamp:
            break;
    }
    return toneMapClamp(x);
}

// The sRGB opto-electronic transfer function, IEC 61966-2-1:1999 section 5.2 (linear [0,1] -> encoded
// [0,1]): a linear toe below 0.0031308, a 1/2.4 power segment above.
inline float srgbEncode(float linear) {
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// Its inverse (IEC 61966-2-1:1999 section 5.2, encoded [0,1] -> linear [0,1]): what 8-bit colour
// textures store. glsl/common/textures.glsl mirrors it.
inline float srgbDecode(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

// Encoded [0,1] -> 8-bit code, rounding to nearest. Out-of-range input is clamped first.
inline std::uint8_t quantize8(float encoded) {
    float v = std::min(std::max(encoded, 0.0f), 1.0f);
    return static_cast<std::uint8_t>(std::floor(v * 255.0f + 0.5f));
}

// One channel of an already-exposed value through tone curve and sRGB encoding.
// Non-finite values get defined results instead of NaN propagating into the PNG: NaN (for example
// 0 * inf from a huge exposure) becomes 0, +inf is tone-mapped to 1 (the limit of every curve after
// the clamp), negatives become 0 (a display cannot emit negative light; Reinhard is undefined at -1).
inline float displayChannel(float exposed, ToneMap toneMap) {
    if (!(exposed > 0.0f)) return 0.0f;  // also catches NaN
    const float mapped =
        std::isinf(exposed) ? 1.0f : std::min(std::max(applyToneMap(exposed, toneMap), 0.0f), 1.0f);
    return srgbEncode(mapped);
}

// A linear pixel to encoded sRGB in [0,1] under `display`. A pixel with any NaN channel is shown black
// and a pixel with any +inf channel (and no NaN) white: a broken sample should stand out as a whole
// pixel, not as a tinted one.
inline glm::vec3 displayEncode(glm::vec3 linear, const DisplaySettings& display) {
    if (std::isnan(linear.r) || std::isnan(linear.g) || std::isnan(linear.b)) return glm::vec3(0.0f);
    const float inf = std::numeric_limits<float>::infinity();
    if (linear.r == inf || linear.g == inf || linear.b == inf) return glm::vec3(srgbEncode(1.0f));
    const float scale = std::exp2(display.exposure);
    return {displayChannel(linear.r * scale, display.toneMap),
            displayChannel(linear.g * scale, display.toneMap),
            displayChannel(linear.b * scale, display.toneMap)};
}

}  // namespace fp
