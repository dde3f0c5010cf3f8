// build/fragpath as a user runs it: exit codes, messages and the files it writes (or must not write).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "cli/fragpath_runner.h"
#include "image/image.h"
#include "image/image_stats.h"
#include "image/rgba8_image.h"

namespace fp {
namespace {

namespace fs = std::filesystem;

using test::CliRun;

CliRun fragpath(const std::string& args, const std::string& environment = "") {
    return test::runFragpath(args, "LP_NUM_THREADS=2 " + environment);
}

class Cli : public test::TempDirTest {
  protected:
    // Expects failure with a message containing `fragment`, and no image written.
    // Exit status 2 for a command line that cannot be read, 1 for any other error (fragpath --help).
    void expectError(const std::string& args, const std::string& fragment, int exitCode = 1) {
        CliRun r = fragpath(args + " -o " + path("out.png"));
        EXPECT_EQ(r.exitCode, exitCode) << r.output;
        EXPECT_NE(r.output.find("fragpath: error: "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(fragment), std::string::npos)
            << "expected '" << fragment << "' in: " << r.output;
        EXPECT_FALSE(fs::exists(path("out.png")));
    }
    // `render A` and `render B` (each to a PFM, quietly) succeed and give the same image bit for bit.
    void expectSameRender(const std::string& a, const std::string& b) {
        CliRun ra = fragpath("render " + a + " --quiet -o " + path("a.pfm"));
        CliRun rb = fragpath("render " + b + " --quiet -o " + path("b.pfm"));
        ASSERT_EQ(ra.exitCode, 0) << ra.output;
        ASSERT_EQ(rb.exitCode, 0) << rb.output;
        EXPECT_EQ(readImage(path("a.pfm")).pixels, readImage(path("b.pfm")).pixels) << a << " against " << b;
    }
};

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n";

TEST_F(Cli, RendersTheBuiltInCornellBoxToEveryFormat) {
    for (const char* ext : {"png", "exr", "pfm"}) {
        CliRun r = fragpath("render --size 16x12 --spp 2 -o " + path(std::string("cornell.") + ext));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("paths/s"), std::string::npos) << r.output;
        EXPECT_TRUE(fs::file_size(path(std::string("cornell.") + ext)) > 0);
    }
    Image exr = readImage(path("cornell.exr")), pfm = readImage(path("cornell.pfm"));
    EXPECT_EQ(exr.width, 16);
    EXPECT_EQ(exr.height, 12);
    EXPECT_EQ(exr.pixels, pfm.pixels) << "same seed, same samples, same linear image in both formats";
    EXPECT_TRUE(allFinite(exr));
    EXPECT_GT(meanColor(exr).x, 0.01);
}

// Options take their value after a space or after '=' (the GNU form), with the same result; a switch
// given a value, or '=' with nothing after it, is an error (issue 17: "--spp=16 is unknown option").
TEST_F(Cli, OptionsTakeTheirValueAfterAnEqualsSign) {
    expectSameRender("--size 8x6 --spp 2 --seed 3", "--size=8x6 --spp=2 --seed=3");
    expectError("render --size 8x6 --quiet=yes", "option --quiet takes no value", 2);
    expectError("render --size 8x6 --spp=", "option --spp needs a value", 2);
    expectError("render --size 8x6 --nonsense=3", "unknown option --nonsense", 2);
}

// --version names the version, the commit the binary was built from (the source tree here is a git
// checkout, so not "unknown") and the OpenGL renderer an offscreen command gets.
TEST_F(Cli, VersionNamesTheCommitAndTheRenderer) {
    CliRun r = fragpath("--version");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.rfind("fragpath ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find("(git "), std::string::npos) << r.output;
    if (fs::exists(fs::path(FP_SOURCE_DIR) / ".git")) {
        EXPECT_EQ(r.output.find("(git unknown"), std::string::npos) << r.output;
    }
    EXPECT_NE(r.output.find("OpenGL: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("llvmpipe"), std::string::npos)
        << "the test machines render with llvmpipe: " << r.output;
}

// The debug views' PNGs show their values (issue 17: depth, nodes and cost came out solid white, their
// raw values clamped): depth from near to far, counts as the viewer's heat map, cost per channel.
TEST_F(Cli, DebugViewsWriteAPngThatShowsTheirValues) {
    for (const char* view : {"depth", "nodes", "cost"}) {
        std::string out = path(std::string(view) + ".png");
        CliRun r = fragpath(std::string("render --view ") + view + " --size 32x32 --spp 1 --quiet -o " + out);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        std::ifstream in(out, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        Rgba8Image png = decodeRgba8(bytes, out);
        std::set<uint32_t> colours;
        size_t white = 0;
        for (size_t i = 0; i < png.texels.size(); i += 4) {
            colours.insert(uint32_t(png.texels[i]) << 16 | uint32_t(png.texels[i + 1]) << 8 |
                           png.texels[i + 2]);
            white += png.texels[i] == 255 && png.texels[i + 1] == 255 && png.texels[i + 2] == 255;
        }
        EXPECT_GE(colours.size(), 3u) << view << ": a PNG of one or two colours shows nothing";
        EXPECT_LT(white, png.texels.size() / 4 / 2) << view << ": mostly white";
    }
}

// --bvh-threads, listed by render --help, is accepted (it was refused as unknown) and changes nothing
// in the image: the builder makes the same tree with any number of threads.
TEST_F(Cli, BvhThreadsIsAcceptedAndChangesNothing) {
    expectSameRender("--size 8x6 --spp 2 --bvh-threads 1", "--size 8x6 --spp 2");
}

// A pass whose shader loops the driver cut short leaves pixels with fewer samples than the render
// counts (llvmpipe stops a shader's loops after a fixed number of iterations in all): the image is written
// and the shortfall reported, as an error under --strict. Simulated with shaders that drop every sample of
// the 4 leftmost columns.
TEST_F(Cli, PixelsWithFewerSamplesThanAskedAreReported) {
    fs::copy(fs::path(FP_SOURCE_DIR) / "glsl", path("glsl"), fs::copy_options::recursive);
    std::ifstream in(path("glsl/passes/trace.frag.glsl"));
    std::string trace((std::istreambuf_iterator<char>(in)), {});
    const std::string add = "void addSample(vec3 c, Ray ray) {\n";
    ASSERT_NE(trace.find(add), std::string::npos);
    trace.replace(trace.find(add), add.size(), add + "    if (gl_FragCoord.x < 4.0) return;\n");
    write("glsl/passes/trace.frag.glsl", trace);
    const std::string render = "render --size 16x8 --spp 3 --shader-dir " + path("glsl");
    CliRun r = fragpath(render + " -o " + path("short.pfm"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("32 pixels hold fewer than 3 samples"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(path("short.pfm")));
    r = fragpath(render + " --strict -o " + path("strict.pfm"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("32 pixels hold fewer than 3 samples"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(path("strict.pfm")));  // the samples are kept
    r = fragpath("render --size 16x8 --spp 3 -o " + path("full.pfm"));  // the built-in shaders
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.output.find("fewer than"), std::string::npos) << r.output;
}

TEST_F(Cli, HelpListsTheOptions) {
    CliRun r = fragpath("render --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* flag : {"--size", "--spp", "--max-depth", "--seed", "--integrator", "--eye", "--target",
                             "--up", "--fov", "--stats", "--exposure", "--tonemap"})
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
}

TEST_F(Cli, StatsReportTheSceneAndTheBvh) {
    CliRun r = fragpath("render --size 8x8 --spp 1 --stats -o " + path("s.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* field :
         {"triangles        32 (2 emissive)", "SAH cost", "gpu memory", "llvmpipe", "rays per path"})
        EXPECT_NE(r.output.find(field), std::string::npos) << field << " in " << r.output;
}

TEST_F(Cli, StatsCountTheImageBuffersOfTheIntegrator) {
    // 8x8 pixels: the accumulation's 2 x 5 RGBA32F attachments (160 bytes per pixel), and for bdpt also
    // its light image (7 record layers, LightSplat::kLightVertices + 1, and 2 attachments, 144 bytes per
    // pixel).
    CliRun nee = fragpath("render --size 8x8 --spp 1 --stats -o " + path("n.png"));
    ASSERT_EQ(nee.exitCode, 0) << nee.output;
    EXPECT_NE(nee.output.find("image buffers    10240 bytes (160 per pixel"), std::string::npos)
        << nee.output;
    CliRun bdpt = fragpath("render --size 8x8 --spp 1 --integrator bdpt --stats -o " + path("b.png"));
    ASSERT_EQ(bdpt.exitCode, 0) << bdpt.output;
    EXPECT_NE(bdpt.output.find("image buffers    19456 bytes (304 per pixel"), std::string::npos)
        << bdpt.output;
}

// The sampler and the indirect clamp come from the flags, else the scene file, else the defaults (sobol,
// no clamp): the scene file's "independent" renders what --sampler independent renders, bit for bit, and
// not what the default renders. Catches a front end that ignores the scene file's choice.
TEST_F(Cli, SamplerAndClampFromTheSceneFile) {
    auto bytes = [](const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    std::string mesh = std::string(FP_SOURCE_DIR) + "/assets/cornell/cornell.obj";
    std::string camera = R"("camera": {"eye": [278, 273, -800], "target": [278, 273, 0], "fov": 39.3})";
    std::string plain = write("plain.json", R"({"mesh": ")" + mesh + R"(", )" + camera + "}");
    std::string chosen =
        write("chosen.json", R"({"mesh": ")" + mesh + R"(", )" + camera +
                                 R"(, "render": {"sampler": "independent", "clamp_indirect": 0.5}})");
    const std::string common = " --size 8x8 --spp 4 -o ";
    ASSERT_EQ(fragpath("render " + chosen + common + path("chosen.pfm")).exitCode, 0);
    ASSERT_EQ(fragpath("render " + plain + common + path("flags.pfm") +
                       " --sampler independent --clamp-indirect 0.5")
                  .exitCode,
              0);
    ASSERT_EQ(fragpath("render " + plain + common + path("default.pfm")).exitCode, 0);
    EXPECT_EQ(bytes(path("chosen.pfm")), bytes(path("flags.pfm")));
    EXPECT_NE(bytes(path("chosen.pfm")), bytes(path("default.pfm")));
}

TEST_F(Cli, CameraFlagsOverrideTheScene) {
    ASSERT_EQ(fragpath("render --size 8x8 --spp 1 -o " + path("a.pfm")).exitCode, 0);
    CliRun r = fragpath("render --size 8x8 --spp 1 --eye 278,273,-800 --target 278,273,0 --fov 10 -o " +
                        path("b.pfm"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(readImage(path("a.pfm")).pixels, readImage(path("b.pfm")).pixels);
}

TEST_F(Cli, RendersAnObjWithoutCameraByFramingIt) {
    CliRun r = fragpath("render " + write("t.obj", kTriangleObj) + " --size 8x8 --spp 1 -o " + path("t.pfm"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("t.pfm")));
}

TEST_F(Cli, BadFlagsAreErrors) {
    expectError("render --bogus", "unknown option --bogus", 2);
    expectError("render --spp", "needs a value", 2);
    expectError("render --spp 0", "--spp");
    expectError("render --spp ten", "--spp");
    expectError("render --size 10", "WIDTHxHEIGHT");
    expectError("render --size 0x10", "WIDTHxHEIGHT");
    expectError("render --max-depth -1", "--max-depth");
    expectError("render --integrator magic", "naive, bsdf, nee or bdpt");
    expectError("render --tonemap sepia", "sepia");
    expectError("render --view xray", "radiance, depth, normal, albedo, bounces, nodes, triangles or cost");
    expectError("render --eye 1,2", "X,Y,Z");
    expectError("render --eye 1,2,nan", "finite");
    expectError("render --fov 180", "field of view");
    expectError("render --eye 1e38,0,0 --target -1e38,0,0 --up 1,0,0", "parallel");
    expectError("render --eye 1,1,1 --target 1,1,1", "same point");
    expectError("render --up 0,0,1", "parallel");
}

TEST_F(Cli, BadInputFilesAreErrorsNamingTheFile) {
    expectError("render " + path("missing.obj"), "missing.obj");
    expectError("render " + dir_.string(), dir_.string());
    expectError("render " + write("empty.obj", ""), "empty.obj");
    expectError("render " + write("bad.obj", "v 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n"), "bad.obj:2");
    expectError("render " + write("bad.json", "{\"mesh\": "), "bad.json");
}

TEST_F(Cli, UnwritableOrUnknownOutputIsAnErrorBeforeRendering) {
    CliRun r = fragpath("render --spp 1 -o " + path("no/such/dir/out.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
    r = fragpath("render --spp 1 -o " + path("out.bmp"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("unknown image format"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("out.bmp")));
}

TEST_F(Cli, NoSuitableGlContextIsAClearError) {
    // Capping Mesa at OpenGL 3.3 leaves no 4.1 core context to create.
    CliRun r = fragpath("render --spp 1 -o " + path("x.png"), "MESA_GL_VERSION_OVERRIDE=3.3");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("could not create an OpenGL 4.1 core context"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("MESA_GL_VERSION_OVERRIDE=3.3 is set"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("x.png")));
    r = fragpath("render --spp 1 -o " + path("x.png"), "GALLIUM_DRIVER=nosuchdriver");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("GALLIUM_DRIVER=nosuchdriver"), std::string::npos) << r.output;
}

TEST_F(Cli, EglAndOsMesaBackendsRenderTheSameImage) {
    // On this machine both reach llvmpipe; the GL_RENDERER line says which renderer was chosen.
    for (const char* backend : {"egl", "osmesa", "auto"}) {
        CliRun r = fragpath(std::string("render --size 16x16 --spp 2 --backend ") + backend + " -o " +
                            path(std::string(backend) + ".pfm"));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("renderer: "), std::string::npos) << r.output;
    }
    EXPECT_EQ(readImage(path("egl.pfm")).pixels, readImage(path("osmesa.pfm")).pixels);
    EXPECT_EQ(readImage(path("auto.pfm")).pixels, readImage(path("osmesa.pfm")).pixels);
    CliRun r = fragpath("render --backend vulkan -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("auto, egl or osmesa"), std::string::npos) << r.output;
}

TEST_F(Cli, InterruptedRenderStillWritesWhatItHas) {
    // SIGINT a long render once it has started; it must write an image of the samples done so far.
    std::string out = path("partial.pfm");
    std::string command = std::string("LP_NUM_THREADS=2 ") + FP_BINARY +
                          " render --size 64x64 --spp 100000 -o " + out + " > " + path("log.txt") +
                          " 2>&1 & pid=$!; sleep 3; kill -INT $pid; wait $pid; echo $? > " + path("code.txt");
    ASSERT_EQ(std::system(command.c_str()), 0);
    std::ifstream code(path("code.txt"));
    int exitCode = -1;
    code >> exitCode;
    std::ifstream logFile(path("log.txt"));
    std::string log((std::istreambuf_iterator<char>(logFile)), std::istreambuf_iterator<char>());
    EXPECT_EQ(exitCode, 130) << log;
    EXPECT_NE(log.find("interrupted after"), std::string::npos) << log;
    Image partial = readImage(out);
    EXPECT_EQ(partial.width, 64);
    EXPECT_GT(meanColor(partial).x, 0.01);
}

}  // namespace
}  // namespace fp
