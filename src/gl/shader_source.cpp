#include "gl/shader_source.h"

#include <fstream>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.h"
#include "gl/embedded_shaders.h"

namespace fp {

ShaderLibrary::ShaderLibrary(std::string directory) : directory_(std::move(directory)) {}

namespace {
// Function statics: a library may be read from during another file's static initialisation.
struct SourcesRead {
    std::mutex mutex;
    std::set<std::string> sources;
};
SourcesRead& sourcesRead() {
    static SourcesRead s;
    return s;
}
}  // namespace

std::set<std::string> ShaderLibrary::takeSourcesRead() {
    std::lock_guard<std::mutex> lock(sourcesRead().mutex);
    return std::exchange(sourcesRead().sources, {});
}

std::string ShaderLibrary::read(const std::string& path) const {
    {
        std::lock_guard<std::mutex> lock(sourcesRead().mutex);
        sourcesRead().sources.insert(directory_);
    }
    if (directory_.empty()) {
        auto it = embeddedShaders().find(path);
        if (it == embeddedShaders().end()) throw Error("no shader file glsl/" + path + " in this build");
        return it->second;
    }
    std::ifstream in(directory_ + "/" + path, std::ios::binary);
    if (!in) throw Error("cannot read shader file " + directory_ + "/" + path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

namespace {

struct Expander {
    const ShaderLibrary& library;
    const ShaderDefines& defines;
    ExpandedShader out;
    std::set<std::string> seen;

    std::string macroPath(const std::string& name) const {
        for (const auto& [key, value] : defines)
            if (key == name && value.size() >= 2 && value.front() == '"' && value.back() == '"')
                return value.substr(1, value.size() - 2);
        throw Error("#include " + name + ": no define of that name holds a quoted path");
    }

    void emit(const std::string& line, const std::string& file, int lineNumber) {
        out.text += line + "\n";
        out.origins.push_back({file, lineNumber});
    }

    void include(const std::string& path) {
        if (!seen.insert(path).second) return;  // every file at most once, like #pragma once
        std::istringstream in(library.read(path));
        // `#include "path"`, or `#include NAME` where NAME is a define whose value is a quoted path.
        static const std::regex includeLine(
            R"re(^\s*#\s*include\s*(?:"([^"]+)"|([A-Za-z_]\w*))\s*(//.*)?$)re");
        static const std::regex conditionalStart(R"re(^\s*#\s*if(def|ndef)?\b.*)re");
        static const std::regex conditionalEnd(R"re(^\s*#\s*endif\b.*)re");
        std::string line;
        int lineNumber = 0;
        int conditionals = 0;  // the #if blocks open at this line of this file
        while (std::getline(in, line)) {
            ++lineNumber;
            std::smatch m;
            if (line.find('#') != std::string::npos) {
                if (std::regex_match(line, conditionalStart)) ++conditionals;
                if (std::regex_match(line, conditionalEnd)) --conditionals;
            }
            if (line.find("include") != std::string::npos && std::regex_match(line, m, includeLine)) {
                // The file is expanded here once, before the preprocessor runs: inside an #if that turns
                // out false its text would be dropped, and every later #include of it skipped.
                if (conditionals > 0)
                    throw Error("glsl/" + path + ":" + std::to_string(lineNumber) +
                                ": #include inside #if: include the file unconditionally");
                try {
                    include(m[1].matched ? m[1].str() : macroPath(m[2].str()));
                } catch (const Error& e) {
                    throw Error("glsl/" + path + ":" + std::to_string(lineNumber) + ": " + e.what());
                }
            } else {
                emit(line, path, lineNumber);
            }
        }
    }
};

}  // namespace

ExpandedShader ShaderLibrary::expand(const std::string& path, const ShaderDefines& defines) const {
    Expander expander{*this, defines, {}, {}};
    expander.emit("#version 410 core", "(generated)", 1);
    for (const auto& [name, value] : defines) {
        bool extension = name.compare(0, 3, "GL_") == 0;
        expander.emit(extension ? "#extension " + name + " : " + value : "#define " + name + " " + value,
                      "(generated)", 1);
    }
    expander.include(path);
    return expander.out;
}

std::string mapCompileLog(const std::string& log, const ExpandedShader& shader) {
    // Mesa "0:12(5): error", AMD "ERROR: 0:12: error", NVIDIA "0(12) : error". The source-string number is
    // ignored: the text carries no #line directives (Mesa drops the source number from some messages), so
    // the line is a line of the whole expanded text, which `origins` maps back to its file.
    static const std::regex reference(R"((\d+):(\d+)\(\d+\)|(\d+):(\d+)(?=:)|(\d+)\((\d+)\)(?= :))");
    std::string result;
    auto begin = std::sregex_iterator(log.begin(), log.end(), reference);
    size_t last = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        int group = m[1].matched ? 1 : m[3].matched ? 3 : 5;
        size_t line = std::stoul(m[group + 1].str());
        result += log.substr(last, size_t(m.position(0)) - last);
        if (line >= 1 && line <= shader.origins.size()) {
            const auto& [file, fileLine] = shader.origins[line - 1];
            result += "glsl/" + file + ":" + std::to_string(fileLine);
        } else {
            result += m.str(0);
        }
        last = size_t(m.position(0) + m.length(0));
    }
    return result + log.substr(last);
}

}  // namespace fp
