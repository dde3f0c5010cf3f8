#include "scene/obj_scan.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "scene/text_syntax.h"

namespace fp {

namespace {

// Quotes a word for a message, shortened so that a megabyte of junk does not become the message.
std::string quoted(std::string_view word) {
    constexpr size_t kMax = 40;
    if (word.size() <= kMax) return "'" + std::string(word) + "'";
    return "'" + std::string(word.substr(0, kMax)) + "...'";
}

// A positive index beyond the elements defined so far may refer to one defined later in the file (as
// tinyobjloader allows), so it can only be checked at the end.
struct ForwardReference {
    int line;
    long long index;
    const char* kind;
};

class Scanner {
  public:
    explicit Scanner(const std::string& name) : name_(name) {}

    ObjScan run(std::string_view text) {
        // The canonical text is about as long as the file: grown once, not doubled and copied.
        out_.text.reserve(text.size() + text.size() / 8);
        LineReader lines(text);
        std::string_view line;
        while (lines.next(&line)) {
            line_ = lines.number();
            statement(line);
            out_.text += '\n';
        }
        checkForwardReferences();
        return std::move(out_);
    }

  private:
    [[noreturn]] void fail(const std::string& message) const {
        throw Error(name_ + ":" + std::to_string(line_) + ": " + message);
    }

    void statement(std::string_view line) {
        // Everything after '#' is a comment; tinyobjloader only knows whole-line comments and would read
        // "f 1 2 3 # quad" as a face with a fourth vertex 0.
        std::string_view code = line.substr(0, line.find('#'));
        splitWords(code, &words_);
        if (words_.empty()) return;
        std::string_view keyword = words_[0];
        if (keyword == "v") {
            vertex();
        } else if (keyword == "vn") {
            normal();
        } else if (keyword == "vt") {
            texcoord();
        } else if (keyword == "f") {
            face();
        } else if (keyword == "usemtl") {
            // The name is the rest of the line: material names may contain blanks.
            std::string_view rest = trimBlanks(trimBlanks(line).substr(keyword.size()));
            out_.text += "usemtl ";
            out_.text += rest;
        } else if (keyword == "mtllib") {
            out_.materialLibraries.push_back({line_, std::string(trimBlanks(trimBlanks(code).substr(6)))});
        }
        // Everything else (o, g, s, l, p, curves...) carries nothing we render.
    }

    // Parses words_[1..] as reals, checking their count is in [minCount, maxCount].
    void reals(const char* what, size_t minCount, size_t maxCount) {
        size_t count = words_.size() - 1;
        if (count < minCount || count > maxCount) {
            std::string expected = minCount == maxCount
                                       ? std::to_string(minCount)
                                       : std::to_string(minCount) + " to " + std::to_string(maxCount);
            fail(std::string(what) + " needs " + expected + " numbers, found " + std::to_string(count));
        }
        values_.clear();
        for (size_t i = 1; i < words_.size(); ++i) {
            std::optional<double> value = parseReal(words_[i]);
            if (!value) fail("malformed number " + quoted(words_[i]) + " in " + what);
            values_.push_back(*value);
        }
    }

    void vertex() {
        // x y z, optionally w, or x y z r g b (a common vertex-colour extension).
        reals("vertex (v)", 3, 7);
        out_.vertexFinite.push_back(finiteXyz());
        ++vertices_;
        appendCanonical(3);
    }

    void normal() {
        reals("vertex normal (vn)", 3, 3);
        out_.normalFinite.push_back(finiteXyz());
        ++normals_;
        appendCanonical(3);
    }

    bool finiteXyz() const {
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(static_cast<float>(values_[i]))) return false;
        return true;
    }

    void texcoord() {
        // u, optionally v and w (a depth for 3D textures, unused); v defaults to 0 as in the OBJ spec.
        reals("texture coordinate (vt)", 1, 3);
        values_.resize(2, 0.0);
        out_.texcoordFinite.push_back(std::isfinite(static_cast<float>(values_[0])) &&
                                      std::isfinite(static_cast<float>(values_[1])));
        ++texcoords_;
        out_.text += "vt ";
        out_.text += words_[1];
        out_.text += words_.size() > 2 ? " " + std::string(words_[2]) : std::string(" 0");
    }

    // Re-spells the statement from its checked words, so tinyobjloader reads exactly them.
    void appendCanonical(size_t count) {
        out_.text += words_[0];
        for (size_t i = 1; i <= count; ++i) {
            out_.text += ' ';
            out_.text += words_[i];
        }
    }

    // Appends `separator` and the decimal digits of `value` (std::to_chars: no temporary strings, which
    // cost a million-triangle file a fifth of its scan).
    static void appendIndex(std::string& out, const char* separator, long long value) {
        char digits[24];
        out += separator;
        out.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
    }

    void face() {
        std::string& canonical = canonical_;  // reused from face to face
        canonical.assign("f");
        size_t corners = words_.size() - 1;
        for (size_t i = 1; i < words_.size(); ++i) {
            std::string_view word = words_[i];
            // v, v/vt, v//vn or v/vt/vn
            size_t slash1 = word.find('/');
            size_t slash2 = slash1 == std::string_view::npos ? slash1 : word.find('/', slash1 + 1);
            if (slash2 != std::string_view::npos && word.find('/', slash2 + 1) != std::string_view::npos)
                fail("malformed face vertex " + quoted(word) + " (expected v, v/vt, v//vn or v/vt/vn)");
            std::string_view v = word.substr(0, slash1);
            std::string_view vt, vn;
            if (slash1 != std::string_view::npos) {
                vt = word.substr(slash1 + 1, slash2 == std::string_view::npos ? std::string_view::npos
                                                                              : slash2 - slash1 - 1);
                if (slash2 != std::string_view::npos) {
                    vn = word.substr(slash2 + 1);
                    if (vn.empty()) fail("malformed face vertex " + quoted(word) + " (empty normal index)");
                } else if (vt.empty()) {
                    fail("malformed face vertex " + quoted(word) + " (empty texture index)");
                }
            }
            appendIndex(canonical, " ", resolve(v, word, "vertex", vertices_));
            if (!vt.empty()) appendIndex(canonical, "/", resolve(vt, word, "texture coordinate", texcoords_));
            if (!vn.empty())
                appendIndex(canonical, vt.empty() ? "//" : "/", resolve(vn, word, "normal", normals_));
        }
        if (corners < 3) {
            out_.shortFaces.add(line_);
            return;
        }
        out_.faceLines.push_back(line_);
        out_.cornerCount += corners;
        out_.text += canonical;
    }

    // The absolute 1-based index `word` stands for, given `defined` elements so far.
    long long resolve(std::string_view index, std::string_view word, const char* kind, long long defined) {
        std::optional<long long> raw = parseInteger(index);
        if (!raw || *raw > std::numeric_limits<int>::max() || *raw < -std::numeric_limits<int>::max())
            fail("malformed " + std::string(kind) + " index " + quoted(index) + " in face vertex " +
                 quoted(word));
        if (*raw == 0)
            fail(std::string(kind) + " index 0 in face vertex " + quoted(word) + " (OBJ indices start at 1)");
        if (*raw < 0) {
            // Relative: -1 is the latest one defined.
            long long absolute = defined + 1 + *raw;
            if (absolute < 1)
                fail("relative " + std::string(kind) + " index " + std::to_string(*raw) +
                     " reaches before the first one (" + std::to_string(defined) + " defined so far)");
            return absolute;
        }
        if (*raw > defined) forward_.push_back({line_, *raw, kind});
        return *raw;
    }

    void checkForwardReferences() {
        for (const ForwardReference& ref : forward_) {
            std::string kind = ref.kind;
            long long defined = kind == "vertex" ? vertices_ : kind == "normal" ? normals_ : texcoords_;
            if (ref.index > defined) {
                line_ = ref.line;
                fail(kind + " index " + std::to_string(ref.index) + " out of range (the file defines " +
                     std::to_string(defined) + ")");
            }
        }
    }

    const std::string& name_;
    ObjScan out_;
    int line_ = 0;
    long long vertices_ = 0, normals_ = 0, texcoords_ = 0;
    std::vector<std::string_view> words_;
    std::string canonical_;
    std::vector<double> values_;
    std::vector<ForwardReference> forward_;
};

}  // namespace

ObjScan scanObj(std::string_view text, const std::string& name) {
    return Scanner(name).run(text);
}

}  // namespace fp
