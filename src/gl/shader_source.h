#pragma once
// GLSL sources with a small #include mechanism. Files come from the embedded glsl/ tree or, for hot
// reloading and experiments, from a directory on disk. Expansion records where every line came from,
// so that compiler messages can be mapped back to the original file and line.
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fp {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

struct ExpandedShader {
    std::string text;  // ready for glShaderSource: #version, defines, then the files
    // For each line of `text` (line n at index n - 1): the file below glsl/ and the line it came from.
    std::vector<std::pair<std::string, int>> origins;
};

class ShaderLibrary {
  public:
    // An empty directory means the shaders compiled into the binary.
    explicit ShaderLibrary(std::string directory = "");
    const std::string& directory() const { return directory_; }

    // The text of one file, by its path below glsl/; throws fp::Error if there is none.
    std::string read(const std::string& path) const;

    // Resolves `#include "path"` (relative to glsl/, each file at most once) and prepends the
    // #version line and the defines. A define named GL_<extension> (GLSL reserves GL_ macro names, so no
    // #define can have one) becomes `#extension GL_<extension> : <value>` instead, in its place before
    // any declaration as GLSL requires. Throws fp::Error naming file and line for a bad include, or one
    // inside an #if (expanded before the preprocessor runs, the file's text would be dropped where the
    // condition is false, and its later #includes skipped as done).
    ExpandedShader expand(const std::string& path, const ShaderDefines& defines) const;

    // Where every library of this process has read files from since the last call: directories, and ""
    // for the shaders compiled in. The tests take it after each test to check that it rendered with the
    // shaders they are pointed at (tests/render/test_shaders.h).
    static std::set<std::string> takeSourcesRead();

  private:
    std::string directory_;
};

// Rewrites "0:12(5): error" style references of a driver's compile log (Mesa, NVIDIA and AMD forms)
// into "glsl/<file>:<line>: error", using the line origins of the expansion.
std::string mapCompileLog(const std::string& log, const ExpandedShader& shader);

}  // namespace fp
