#include "gl/shader_source.h"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.h"
#include "gl/embedded_shaders.h"

namespace fp {

ShaderLibrary::ShaderLibrary(std::string directory) : directory_(std::move(directory)) {}

std::string ShaderLibrary::read(const std::string& path) const {
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

    void include(const std::string& path) {
        if (!seen.insert(path).second) return;  // every file at most once, like #pragma once
        int fileIndex = int(out.files.size());
        out.files.push_back(path);
        std::istringstream in(library.read(path));
        out.text += "#line 1 " + std::to_string(fileIndex) + "\n";
        // `#include "path"`, or `#include NAME` where NAME is a define whose value is a quoted path.
        static const std::regex includeLine(
            R"re(^\s*#\s*include\s*(?:"([^"]+)"|([A-Za-z_]\w*))\s*(//.*)?$)re");
        std::string line;
        int lineNumber = 0;
        while (std::getline(in, line)) {
            ++lineNumber;
            std::smatch m;
            if (line.find("include") != std::string::npos && std::regex_match(line, m, includeLine)) {
                try {
                    include(m[1].matched ? m[1].str() : macroPath(m[2].str()));
                } catch (const Error& e) {
                    throw Error("glsl/" + path + ":" + std::to_string(lineNumber) + ": " + e.what());
                }
                // GLSL 4.x: the line after `#line L F` is line L.
                out.text +=
                    "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(fileIndex) + "\n";
            } else {
                out.text += line + "\n";
            }
        }
    }
};

}  // namespace

ExpandedShader ShaderLibrary::expand(const std::string& path, const ShaderDefines& defines) const {
    Expander expander{*this, defines, {}, {}};
    expander.out.text = "#version 410 core\n";
    for (const auto& [name, value] : defines) expander.out.text += "#define " + name + " " + value + "\n";
    expander.include(path);
    return expander.out;
}

std::string mapCompileLog(const std::string& log, const std::vector<std::string>& files) {
    // Mesa "0:12(5): error", AMD "ERROR: 0:12: error", NVIDIA "0(12) : error".
    static const std::regex reference(R"((\d+):(\d+)\(\d+\)|(\d+):(\d+)(?=:)|(\d+)\((\d+)\)(?= :))");
    std::string result;
    auto begin = std::sregex_iterator(log.begin(), log.end(), reference);
    size_t last = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        int group = m[1].matched ? 1 : m[3].matched ? 3 : 5;
        size_t file = std::stoul(m[group].str());
        result += log.substr(last, size_t(m.position(0)) - last);
        if (file < files.size())
            result += "glsl/" + files[file] + ":" + m[group + 1].str();
        else
            result += m.str(0);
        last = size_t(m.position(0) + m.length(0));
    }
    return result + log.substr(last);
}

}  // namespace fp
