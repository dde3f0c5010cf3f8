#include "image/tone_map.h"

#include "core/text.h"

namespace fp {

ToneMap parseToneMap(const std::string& name) {
    return parseName(name, kAllToneMaps, toneMapName, "tone map");
}

const char* toneMapName(ToneMap toneMap) {
    static constexpr const char* kNames[] = {"clamp", "reinhard", "aces"};  // in enum order
    return nameOf(toneMap, kNames);
}

}  // namespace fp
