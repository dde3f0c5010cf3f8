#include "image/tone_map.h"

#include "core/error.h"

namespace fp {

ToneMap parseToneMap(const std::string& name) {
    if (name == "clamp") return ToneMap::Clamp;
    if (name == "reinhard") return ToneMap::Reinhard;
    if (name == "aces") return ToneMap::Aces;
    throw Error("unknown tone map '" + name + "' (choose clamp, reinhard or aces)");
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
