#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "core/log.h"
#include "scene/mtl.h"
#include "scene/repair_tally.h"
#include "scene/text_file.h"
#include "scene/text_syntax.h"

namespace fp {

namespace {

// A RepairTally that also names the statements it counted ("Kd/Ke"), in the order they first occurred,
// so that one warning covers a kind of repair whichever statements needed it.
class KeyedTally {
  public:
    void add(std::string_view key, int line) {
        tally_.add(line);
        if (std::find(keys_.begin(), keys_.end(), key) == keys_.end()) keys_.emplace_back(key);
    }
    // Warns "<file>: <verb> <count> <adjective> <keys> <noun>[s] <rest> (first at line L)".
    void report(const std::string& file, const std::string& verb, const std::string& adjective,
                const std::string& noun, const std::string& rest = "") const {
        std::string keys;
        for (const std::string& k : keys_) keys += (keys.empty() ? "" : "/") + k;
        tally_.report(file, verb, (adjective.empty() ? "" : adjective + " ") + keys + " " + noun, rest);
    }

  private:
    RepairTally tally_;
    std::vector<std::string> keys_;
};

struct MtlRepairs {
    KeyedTally clamped, negative, nonFinite, malformed, unsupported, nonFiniteScalar, mapOptions;
    std::vector<std::string> optionStatements;  // the map statements whose options were ignored
    RepairTally iorClamped;
    std::vector<std::pair<std::string, int>> unknown;  // statement name and first line, in file order

    void report(const std::string& name) const {
        clamped.report(name, "clamped", "", "value", "to [0, 1]");
        negative.report(name, "set", "negative", "value", "to 0");
        nonFinite.report(name, "replaced", "NaN or infinite", "value", "by 0");
        malformed.report(name, "ignored", "malformed", "statement");
        unsupported.report(name, "ignored", "spectral or CIE XYZ", "statement", "(only RGB is supported)");
        nonFiniteScalar.report(name, "ignored", "", "statement", "with a NaN or infinite value");
        iorClamped.report(name, "clamped", "Ni value", "to [1, 4]");
        std::string statements;
        for (const std::string& k : optionStatements) statements += (statements.empty() ? "" : "/") + k;
        mapOptions.report(name, "ignored", statements, "option", "(textures repeat, unscaled and unshifted)");
        for (const auto& [key, line] : unknown)
            warn(name + ": unknown MTL statement '" + key + "' ignored (first at line " +
                 std::to_string(line) + ")");
    }
};

// Statements we read (re-spelled below) or accept without using them. Anything else is reported once.
bool isKnownStatement(std::string_view key) {
    static const std::string_view kKnown[] = {
        "newmtl", "Ka",   "Kd",        "Ks",   "Ke",   "Kt",    "Tf",   "Ni",  "Ns",
        "d",      "Tr",   "illum",     "Pr",   "Pm",   "Ps",    "Pc",   "Pcr", "aniso",
        "anisor", "norm", "sharpness", "bump", "disp", "decal", "refl", "Vd"};
    if (key.substr(0, 4) == "map_") return true;
    return std::find(std::begin(kKnown), std::end(kKnown), key) != std::end(kKnown);
}

bool isColorStatement(std::string_view key) {
    return key == "Kd" || key == "Ke" || key == "Ks" || key == "Tf" || key == "Kt";
}

bool isScalarStatement(std::string_view key) {
    return key == "Ni" || key == "Ns" || key == "Pr" || key == "Pm" || key == "Vd" || key == "illum" ||
           key == "d";
}

// The texture map statements we read (mtl.h), by name; bump and map_bump are map_Bump.
std::optional<MtlMap> mapOf(std::string_view key) {
    static const std::pair<std::string_view, MtlMap> kMaps[] = {
        {"map_Kd", MtlMap::Kd}, {"map_Ks", MtlMap::Ks},     {"map_Ke", MtlMap::Ke},
        {"map_Pr", MtlMap::Pr}, {"map_Pm", MtlMap::Pm},     {"map_d", MtlMap::D},
        {"norm", MtlMap::Norm}, {"map_Bump", MtlMap::Bump}, {"map_bump", MtlMap::Bump},
        {"bump", MtlMap::Bump}};
    for (const auto& [name, map] : kMaps)
        if (name == key) return map;
    return std::nullopt;
}

// The options of a texture map statement (MTL spec, "Texture map statements") and how many values each
// takes; -o, -s and -t take one to three numbers. We read -bm of normal maps and -imfchan of scalar
// maps; every other option is reported as ignored.
int mapOptionValues(std::string_view option, bool* variable) {
    static const std::pair<std::string_view, int> kOptions[] = {
        {"-blendu", 1}, {"-blendv", 1},  {"-bm", 1}, {"-boost", 1},  {"-cc", 1},
        {"-clamp", 1},  {"-imfchan", 1}, {"-mm", 2}, {"-texres", 1}, {"-type", 1},
        {"-o", 3},      {"-s", 3},       {"-t", 3}};
    *variable = option == "-o" || option == "-s" || option == "-t";
    for (const auto& [name, count] : kOptions)
        if (name == option) return count;
    return 0;  // unknown: the option alone
}

// "map_X [options] file": records the file (the rest of the line after the options, so that names
// with blanks work; backslash separators, as some Windows exporters write them, become '/') and the
// options we read in `map`, reports the others as ignored, and returns false if no file name is left.
bool mapStatement(std::string_view code, const std::vector<std::string_view>& words, int line, MtlMap kind,
                  MtlRepairs* repairs, MtlMapStatement* map) {
    const bool normal = kind == MtlMap::Norm || kind == MtlMap::Bump;
    const bool scalar = kind == MtlMap::Pr || kind == MtlMap::Pm || kind == MtlMap::D;
    MtlMapStatement out;
    size_t i = 1;
    while (i < words.size() && words[i].size() > 1 && words[i][0] == '-') {
        std::string_view option = words[i];
        bool variable = false;
        int values = mapOptionValues(option, &variable);
        ++i;
        bool read = false;
        if (option == "-bm" && normal && i < words.size()) {
            std::optional<double> scale = parseReal(words[i]);
            read = scale && std::isfinite(float(*scale));
            if (read) out.bumpScale = float(*scale);
        } else if (option == "-imfchan" && scalar && i < words.size()) {
            read =
                words[i] == "r" || words[i] == "g" || words[i] == "b" || words[i] == "m" || words[i] == "l";
            if (read) out.channel = words[i][0];
        }
        if (!read) {
            repairs->mapOptions.add(option, line);
            std::string statement(words[0] == "bump" || words[0] == "map_bump" ? "map_Bump" : words[0]);
            if (std::find(repairs->optionStatements.begin(), repairs->optionStatements.end(), statement) ==
                repairs->optionStatements.end())
                repairs->optionStatements.push_back(statement);
        }
        for (int v = 0; v < values && i < words.size(); ++v, ++i)
            if (variable && v > 0 && !parseReal(words[i])) break;
    }
    if (i >= words.size()) return false;
    std::string file(trimBlanks(code.substr(size_t(words[i].data() - code.data()))));
    std::replace(file.begin(), file.end(), '\\', '/');
    out.file = file;
    out.line = line;
    *map = out;
    return true;
}

// One colour statement, re-spelled with three checked values; empty if it has to be dropped. Ke is a
// radiance (any non-negative value); the others are reflectances or filters, in [0, 1].
std::string colorStatement(const std::vector<std::string_view>& words, int line, MtlRepairs* repairs,
                           MtlGiven* given) {
    std::string_view keyword = words[0];
    if (words.size() >= 2 && (words[1] == "spectral" || words[1] == "xyz")) {
        repairs->unsupported.add(keyword, line);
        return "";
    }
    // "Kd r g b", or "Kd g" meaning grey (r = g = b), as the MTL spec defines it.
    if (words.size() != 2 && words.size() != 4) {
        repairs->malformed.add(keyword, line);
        return "";
    }
    std::string out(keyword);
    for (int c = 0; c < 3; ++c) {
        std::string_view word = words[words.size() == 2 ? 1 : 1 + c];
        std::optional<double> value = parseReal(word);
        if (!value) {
            repairs->malformed.add(keyword, line);
            return "";
        }
        std::string spelled(word);
        if (!std::isfinite(static_cast<float>(*value))) {
            repairs->nonFinite.add(keyword, line);
            spelled = "0";
        } else if (keyword != "Ke" && (*value < 0.0 || *value > 1.0)) {
            repairs->clamped.add(keyword, line);
            spelled = *value < 0.0 ? "0" : "1";
        } else if (keyword == "Ke" && *value < 0.0) {
            repairs->negative.add(keyword, line);
            spelled = "0";
        }
        out += ' ' + spelled;
    }
    if (keyword == "Kd") given->kd = true;
    if (keyword == "Ke") given->ke = true;
    if (keyword == "Ks") given->ks = true;
    return out;
}

// One Ni, Ns, Pr, Pm or illum statement, re-spelled with its checked value; empty if it has to be
// dropped (the material then counts as not giving it). Marks it in `given` when kept.
std::string scalarStatement(const std::vector<std::string_view>& words, int line, MtlRepairs* repairs,
                            MtlGiven* given) {
    std::string_view keyword = words[0];
    if (words.size() != 2) {
        repairs->malformed.add(keyword, line);
        return "";
    }
    std::string out(keyword);
    if (keyword == "illum") {
        // tinyobjloader reads it with atoi, which takes "abc" as 0 and "2.5" as 2.
        std::optional<long long> model = parseInteger(words[1]);
        if (!model || *model < 0 || *model > std::numeric_limits<int>::max()) {
            repairs->malformed.add(keyword, line);
            return "";
        }
        given->illum = true;
        return out + ' ' + std::to_string(*model);
    }
    std::optional<double> value = parseReal(words[1]);
    if (!value) {
        repairs->malformed.add(keyword, line);
        return "";
    }
    if (!std::isfinite(static_cast<float>(*value))) {
        repairs->nonFiniteScalar.add(keyword, line);
        return "";
    }
    std::string spelled(words[1]);
    if (keyword == "Ni" && (*value < 1.0 || *value > 4.0)) {
        // Below 1 is physically odd (light faster than in vacuum); above 4 no common material goes.
        repairs->iorClamped.add(line);
        spelled = *value < 1.0 ? "1" : "4";
    } else if (keyword == "Ns" && *value < 0.0) {
        repairs->negative.add(keyword, line);
        spelled = "0";
    } else if (keyword == "Vd" && *value != 0.0 && (*value < 10.0 || *value > 100.0)) {
        // Optical glasses have Abbe numbers between about 17 and 95; 0 means no dispersion.
        repairs->clamped.add(keyword, line);
        spelled = *value < 10.0 ? "10" : "100";
    } else if ((keyword == "Pr" || keyword == "Pm" || keyword == "d") && (*value < 0.0 || *value > 1.0)) {
        repairs->clamped.add(keyword, line);
        spelled = *value < 0.0 ? "0" : "1";
    }
    if (keyword == "Ni") given->ni = true;
    if (keyword == "Ns") given->ns = true;
    if (keyword == "Pr") given->pr = true;
    if (keyword == "Pm") given->pm = true;
    if (keyword == "Vd") given->vd = true;
    if (keyword == "d") given->d = true;
    return out + ' ' + spelled;
}

}  // namespace

std::string sanitizeMtl(std::string_view text, const std::string& name, std::vector<MtlGiven>* given) {
    MtlRepairs repairs;
    std::deque<MtlGiven> materials;  // a deque keeps `current` valid as it grows
    MtlGiven beforeFirst;  // statements before any newmtl: tinyobjloader returns no material for them
    MtlGiven* current = &beforeFirst;
    std::string out;
    out.reserve(text.size() + 64);
    LineReader lines(stripUtf8Bom(text));
    std::string_view line;
    std::vector<std::string_view> words;
    while (lines.next(&line)) {
        splitWords(line.substr(0, line.find('#')), &words);
        if (words.empty()) {
            out += line;
        } else if (words[0] == "newmtl") {
            // Like usemtl in the OBJ scan: the name is the rest of the line, without surrounding blanks.
            std::string_view material = trimBlanks(trimBlanks(line).substr(6));
            out += "newmtl ";
            out += material;
            // tinyobjloader ignores "newmtl" without a name (the statements after it go on filling the
            // previous material), so only a named one starts an entry of `given`.
            if (!material.empty()) current = &materials.emplace_back();
        } else if (isColorStatement(words[0])) {
            out += colorStatement(words, lines.number(), &repairs, current);
        } else if (isScalarStatement(words[0])) {
            out += scalarStatement(words, lines.number(), &repairs, current);
        } else {
            if (std::optional<MtlMap> map = mapOf(words[0])) {
                if (!mapStatement(line.substr(0, line.find('#')), words, lines.number(), *map, &repairs,
                                  &current->maps[size_t(*map)]))
                    repairs.malformed.add(words[0], lines.number());
            }
            if (!isKnownStatement(words[0])) {
                auto seen = std::find_if(repairs.unknown.begin(), repairs.unknown.end(),
                                         [&](const auto& u) { return u.first == words[0]; });
                if (seen == repairs.unknown.end()) repairs.unknown.emplace_back(words[0], lines.number());
            }
            out += line;
        }
        out += '\n';
    }
    repairs.report(name);
    if (given) given->assign(materials.begin(), materials.end());
    return out;
}

}  // namespace fp
