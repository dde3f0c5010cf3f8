#include "image/tone_map.h"

#include "core/text.h"

namespace fp {

ToneMap parseToneMap(const std::string& name) {
    return parseName(name, kAllToneMaps, toneMapName, "tone map");
}

const char* toneMapName(ToneMap toneMap) {
    switch (toneMap) {
        case ToneMap::Reinhard:
            return "reinhard";
        case ToneMap::Aces:
            return "aces";
        case ToneMap::Clamp:
            break;
    }
    return "clamp";
}

}  // namespace fp
