#include <cmath>

#include "scene/mtl.h"
#include "scene/repair_tally.h"
#include "scene/text_file.h"
#include "scene/text_syntax.h"

namespace fp {

namespace {

struct MtlRepairs {
    RepairTally clamped, negative, nonFinite, malformed, unsupported;

    void report(const std::string& name) const {
        clamped.report(name, "clamped", "Kd value", "to [0, 1]");
        negative.report(name, "set", "negative Ke value", "to 0");
        nonFinite.report(name, "replaced", "NaN or infinite Kd/Ke value", "by 0");
        malformed.report(name, "ignored", "malformed Kd/Ke statement");
        unsupported.report(name, "ignored", "spectral or CIE XYZ Kd/Ke statement", "(only RGB is supported)");
    }
};

// One Kd or Ke statement, re-spelled with three checked values; empty if it has to be dropped.
std::string colorStatement(const std::vector<std::string_view>& words, int line, MtlRepairs* repairs) {
    std::string_view keyword = words[0];
    if (words.size() >= 2 && (words[1] == "spectral" || words[1] == "xyz")) {
        repairs->unsupported.add(line);
        return "";
    }
    // "Kd r g b", or "Kd g" meaning grey (r = g = b), as the MTL spec defines it.
    if (words.size() != 2 && words.size() != 4) {
        repairs->malformed.add(line);
        return "";
    }
    std::string out(keyword);
    for (int c = 0; c < 3; ++c) {
        std::string_view word = words[words.size() == 2 ? 1 : 1 + c];
        std::optional<double> value = parseReal(word);
        if (!value) {
            repairs->malformed.add(line);
            return "";
        }
        std::string spelled(word);
        if (!std::isfinite(static_cast<float>(*value))) {
            repairs->nonFinite.add(line);
            spelled = "0";
        } else if (keyword == "Kd" && (*value < 0.0 || *value > 1.0)) {
            repairs->clamped.add(line);
            spelled = *value < 0.0 ? "0" : "1";
        } else if (keyword == "Ke" && *value < 0.0) {
            repairs->negative.add(line);
            spelled = "0";
        }
        out += ' ' + spelled;
    }
    return out;
}

}  // namespace

std::string sanitizeMtl(std::string_view text, const std::string& name) {
    MtlRepairs repairs;
    std::string out;
    out.reserve(text.size() + 64);
    LineReader lines(stripUtf8Bom(text));
    std::string_view line;
    std::vector<std::string_view> words;
    while (lines.next(&line)) {
        splitWords(line.substr(0, line.find('#')), &words);
        if (!words.empty() && words[0] == "newmtl") {
            // Like usemtl in the OBJ scan: the name is the rest of the line, without surrounding blanks.
            out += "newmtl ";
            out += trimBlanks(trimBlanks(line).substr(6));
        } else if (!words.empty() && (words[0] == "Kd" || words[0] == "Ke")) {
            out += colorStatement(words, lines.number(), &repairs);
        } else {
            out += line;
        }
        out += '\n';
    }
    repairs.report(name);
    return out;
}

}  // namespace fp
