// The #include mechanism and the mapping of compiler messages back to glsl/<file>:<line>.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "gl/context.h"
#include "gl/program.h"
#include "gl/shader_source.h"

namespace fp {
namespace {

namespace fs = std::filesystem;

class ShaderDir : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("fragpath_glsl_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_ / "common");
    }
    void TearDown() override { fs::remove_all(dir_); }
    void write(const std::string& path, const std::string& text) { std::ofstream(dir_ / path) << text; }
    fs::path dir_;
};

TEST_F(ShaderDir, IncludesAreExpandedOnceWithLineDirectives) {
    write("common/a.glsl", "float a() { return 1.0; }\n");
    write("common/b.glsl", "#include \"common/a.glsl\"\nfloat b() { return a(); }\n");
    write("main.glsl", "#include \"common/a.glsl\"\n#include \"common/b.glsl\"\nvoid main() {}\n");
    ExpandedShader e = ShaderLibrary(dir_.string()).expand("main.glsl", {{"N", "3"}});
    EXPECT_EQ(e.files, (std::vector<std::string>{"main.glsl", "common/a.glsl", "common/b.glsl"}));
    EXPECT_EQ(e.text.rfind("#version 410 core\n#define N 3\n", 0), 0u);
    // a.glsl appears once although both main and b include it.
    size_t first = e.text.find("float a()");
    EXPECT_NE(first, std::string::npos);
    EXPECT_EQ(e.text.find("float a()", first + 1), std::string::npos);
    // After b's include of a, b resumes at its line 2; after main's includes, main resumes at line 3.
    EXPECT_NE(e.text.find("#line 2 2\nfloat b()"), std::string::npos);
    EXPECT_NE(e.text.find("#line 3 0\nvoid main()"), std::string::npos);
}

TEST_F(ShaderDir, IncludeThroughADefineNamingAPath) {
    write("chosen.glsl", "float chosen;\n");
    write("main.glsl", "#include PICK\n");
    ExpandedShader e = ShaderLibrary(dir_.string()).expand("main.glsl", {{"PICK", "\"chosen.glsl\""}});
    EXPECT_NE(e.text.find("float chosen;"), std::string::npos);
    EXPECT_THROW(ShaderLibrary(dir_.string()).expand("main.glsl", {}), Error);
}

TEST_F(ShaderDir, MissingIncludeNamesTheIncludingFileAndLine) {
    write("main.glsl", "// first\n#include \"nowhere.glsl\"\n");
    try {
        ShaderLibrary(dir_.string()).expand("main.glsl", {});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("glsl/main.glsl:2"), std::string::npos) << e.what();
    }
}

TEST(CompileLog, DriverReferencesBecomeFileAndLine) {
    std::vector<std::string> files = {"passes/trace.frag.glsl", "common/rng.glsl"};
    EXPECT_EQ(mapCompileLog("1:12(5): error: `x' undeclared", files),
              "glsl/common/rng.glsl:12: error: `x' undeclared");
    EXPECT_EQ(mapCompileLog("ERROR: 0:7: 'y' : undeclared", files),
              "ERROR: glsl/passes/trace.frag.glsl:7: 'y' : undeclared");
    EXPECT_EQ(mapCompileLog("1(3) : error C1008: undefined", files),
              "glsl/common/rng.glsl:3 : error C1008: undefined");
}

TEST(EmbeddedShaders, EveryShippedFileExpands) {
    ShaderLibrary embedded;
    EXPECT_NO_THROW(embedded.expand("passes/fullscreen.vert.glsl", {}));
    EXPECT_THROW(embedded.read("no/such.glsl"), Error);
}

TEST_F(ShaderDir, RealCompileErrorReportsTheOriginalFileAndLine) {
    static std::unique_ptr<GlContext> context = createOsMesaContext();
    write("vert.glsl", "void main() { gl_Position = vec4(0.0); }\n");
    write("common/broken.glsl",
          "// a comment\nfloat ok() { return 1.0; }\nfloat broken() { return undeclaredThing; }\n");
    write("frag.glsl",
          "#include \"common/broken.glsl\"\nout vec4 color;\nvoid main() { color = vec4(broken()); }\n");
    try {
        Program program(ShaderLibrary(dir_.string()), "vert.glsl", "frag.glsl");
        FAIL() << "expected a compile error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("glsl/common/broken.glsl:3"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace fp
