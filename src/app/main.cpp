// build/fragpath: one binary, one subcommand per front end.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/error.h"
#include "git_commit.h"  // generated at build time (cmake/git_commit.cmake)
#include "gl/context.h"

static const char* kUsage =
    "fragpath: a path tracer that runs in an OpenGL fragment shader\n"
    "\n"
    "usage: fragpath <command> [options]\n"
    "\n"
    "commands:\n"
    "  render [SCENE]   render an OBJ or scene file (default: the built-in Cornell box) to an image\n"
    "  bench [SCENE]    measure time to first frame, paths/s and rays/s (median of several runs)\n"
    "  view [SCENE]     open a window that renders interactively (needs a display, or xvfb-run)\n"
    "  merge PARTS -o OUT.exr  combine partial renders of disjoint sample ranges into one image\n"
    "  study [SCENE]    how much noise is too much: error and time against samples, feasibility report\n"
    "  compare TEST REF  one error figure between two images: FLIP (perceptual), RMSE, relMSE or SSIM\n"
    "  realtime [SCENE] --out DIR  a camera path at a frame budget, with temporal reuse and filtering\n"
    "\n"
    "Run 'fragpath <command> --help' for the options of a command; 'fragpath --version' prints the\n"
    "version, the git commit and the OpenGL renderer the offscreen commands would use.\n"
    "\n"
    "exit status: 0 done, 1 an error in the input or the environment (the message says which), 2 a\n"
    "command line that cannot be read (no or unknown command, unknown option, missing value), 3 an\n"
    "internal error (a bug: please report it). Ctrl-C during a render: 130, after writing what it has.\n";

// The version, the commit and what an offscreen context gets here (or why it gets none).
int printVersion() {
    std::printf("fragpath %s (git %s)\n", FP_VERSION, FP_GIT_COMMIT);
    try {
        std::unique_ptr<fp::GlContext> context = fp::createOffscreenContext(fp::kAutoBackend);
        std::printf("OpenGL: %s\n", context->description().c_str());
    } catch (const fp::Error& e) {
        std::printf("OpenGL: no offscreen context (%s)\n", e.what());
    }
    return 0;
}

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(kUsage, args.empty() ? stderr : stdout);
        return args.empty() ? 2 : 0;
    }
    if (args[0] == "--version" || args[0] == "version") return printVersion();
    std::string command = args[0];
    args.erase(args.begin());
    try {
        if (command == "render") return fp::renderCommand(args);
        if (command == "bench") return fp::benchCommand(args);
        if (command == "view") return fp::viewCommand(args);
        if (command == "merge") return fp::mergeCommand(args);
        if (command == "study") return fp::studyCommand(args);
        if (command == "compare") return fp::compareCommand(args);
        if (command == "realtime") return fp::realtimeCommand(args);
        std::fprintf(stderr, "fragpath: unknown command '%s'\n\n%s", command.c_str(), kUsage);
        return 2;
    } catch (const fp::UsageError& e) {
        std::fprintf(stderr, "fragpath: error: %s\n", e.what());
        return 2;
    } catch (const fp::Error& e) {
        std::fprintf(stderr, "fragpath: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fragpath: internal error: %s\n", e.what());
        return 3;
    }
}
