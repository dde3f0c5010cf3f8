// The #include mechanism and the mapping of compiler messages back to glsl/<file>:<line>.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "core/error.h"
#include "gl/context.h"
#include "gl/embedded_shaders.h"
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

TEST_F(ShaderDir, IncludesAreExpandedOnceAndEveryLineKnowsItsOrigin) {
    write("common/a.glsl", "float a() { return 1.0; }\n");
    write("common/b.glsl", "#include \"common/a.glsl\"\nfloat b() { return a(); }\n");
    write("main.glsl", "#include \"common/a.glsl\"\n#include \"common/b.glsl\"\nvoid main() {}\n");
    ExpandedShader e = ShaderLibrary(dir_.string()).expand("main.glsl", {{"N", "3"}});
    EXPECT_EQ(e.text,
              "#version 410 core\n#define N 3\nfloat a() { return 1.0; }\nfloat b() { return a(); }\nvoid "
              "main() {}\n");
    using Origin = std::pair<std::string, int>;
    EXPECT_EQ(e.origins, (std::vector<Origin>{{"(generated)", 1},
                                              {"(generated)", 1},
                                              {"common/a.glsl", 1},
                                              {"common/b.glsl", 2},
                                              {"main.glsl", 3}}));
}

TEST_F(ShaderDir, IncludeThroughADefineNamingAPath) {
    write("chosen.glsl", "float chosen;\n");
    write("main.glsl", "#include PICK\n");
    ExpandedShader e = ShaderLibrary(dir_.string()).expand("main.glsl", {{"PICK", "\"chosen.glsl\""}});
    EXPECT_NE(e.text.find("float chosen;"), std::string::npos);
    EXPECT_THROW(ShaderLibrary(dir_.string()).expand("main.glsl", {}), Error);
}

TEST_F(ShaderDir, AGlNamedDefineBecomesAnExtensionDirective) {
    write("main.glsl", "void main() {}\n");
    ExpandedShader e = ShaderLibrary(dir_.string())
                           .expand("main.glsl", {{"GL_ARB_shader_image_load_store", "require"}, {"N", "1"}});
    EXPECT_EQ(e.text,
              "#version 410 core\n#extension GL_ARB_shader_image_load_store : require\n#define N 1\nvoid "
              "main() {}\n");
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

// An include inside #if is refused: expanded before the preprocessor runs, the file would be marked
// included even where the condition drops its text, so a later unconditional include would find nothing.
TEST_F(ShaderDir, IncludeInsideAConditionalIsRefused) {
    write("common/a.glsl", "float a() { return 1.0; }\n");
    write("main.glsl", "#if FEATURE\n#ifdef X\n#endif\n#include \"common/a.glsl\"\n#endif\nvoid main() {}\n");
    try {
        ShaderLibrary(dir_.string()).expand("main.glsl", {{"FEATURE", "0"}});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("glsl/main.glsl:4: #include inside #if"), std::string::npos)
            << e.what();
    }
    write("main.glsl",
          "#ifndef FEATURE\n#define FEATURE 0\n#endif\n#include \"common/a.glsl\"\nvoid main() {}\n");
    EXPECT_NE(ShaderLibrary(dir_.string()).expand("main.glsl", {}).text.find("float a()"), std::string::npos)
        << "after the #endif it is unconditional";
}

TEST(CompileLog, DriverReferencesBecomeFileAndLine) {
    ExpandedShader e;
    e.origins = {
        {"(generated)", 1}, {"passes/trace.frag.glsl", 1}, {"common/rng.glsl", 12}, {"common/rng.glsl", 13}};
    // The source-string number is ignored: Mesa reports 0 for some errors whatever the file.
    EXPECT_EQ(mapCompileLog("0:3(5): error: `x' undeclared", e),
              "glsl/common/rng.glsl:12: error: `x' undeclared");
    EXPECT_EQ(mapCompileLog("ERROR: 0:2: 'y' : undeclared", e),
              "ERROR: glsl/passes/trace.frag.glsl:1: 'y' : undeclared");
    EXPECT_EQ(mapCompileLog("0(4) : error C1008: undefined", e),
              "glsl/common/rng.glsl:13 : error C1008: undefined");
    EXPECT_EQ(mapCompileLog("0:99(1): beyond the text", e), "0:99(1): beyond the text");
}

TEST(EmbeddedShaders, EveryShippedFileExpands) {
    ShaderLibrary embedded;
    EXPECT_NO_THROW(embedded.expand("passes/fullscreen.vert.glsl", {}));
    EXPECT_THROW(embedded.read("no/such.glsl"), Error);
}

// Where shaders were read from, taken once (what tests/render/test_shaders.h checks after every test): the
// embedded copy as "", a directory by its name; nothing that was only constructed.
TEST_F(ShaderDir, SourcesReadAreTakenOnce) {
    write("main.glsl", "void main() {}\n");
    ShaderLibrary::takeSourcesRead();  // whatever earlier tests read
    ShaderLibrary unused("/no/such/directory");
    ShaderLibrary(dir_.string()).expand("main.glsl", {});
    ShaderLibrary().read("passes/fullscreen.vert.glsl");
    EXPECT_EQ(ShaderLibrary::takeSourcesRead(), (std::set<std::string>{"", dir_.string()}));
    EXPECT_TRUE(ShaderLibrary::takeSourcesRead().empty());
}

// The GPU tests render with the source tree's glsl/ (tests/render/test_shaders.h), so that a copy of it
// with a deliberate bias reaches every one of them; what they vouch for is the copy compiled into the
// binary only if the two hold the same files, byte for byte.
TEST(EmbeddedShaders, AreTheSourceTreesFiles) {
    const fs::path root = FP_SOURCE_DIR "/glsl";
    size_t onDisk = 0;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".glsl") continue;
        ++onDisk;
        const std::string path = fs::relative(entry.path(), root).generic_string();
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        auto it = embeddedShaders().find(path);
        ASSERT_NE(it, embeddedShaders().end()) << "glsl/" << path << " is not compiled in: rebuild";
        EXPECT_EQ(it->second, text) << "glsl/" << path << " differs from the copy compiled in: rebuild";
    }
    EXPECT_GT(onDisk, 30u);
    EXPECT_EQ(embeddedShaders().size(), onDisk) << "files compiled in that the source tree no longer has";
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
        std::string message = e.what();
        EXPECT_NE(message.find("glsl/common/broken.glsl:3: error: `undeclaredThing' undeclared"),
                  std::string::npos)
            << message;
        EXPECT_EQ(message.find("frag.glsl:3"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace fp
