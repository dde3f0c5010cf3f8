#pragma once
// The desktop viewer: a GLFW window that shows the renderer's accumulation as it refines, with an
// interactive camera, a Dear ImGui panel and shader hot reload. It drives the same Renderer and
// Display as every other front end; `fragpath view` parses flags into ViewerOptions and calls runViewer.
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "viewer/viewer_controls.h"

namespace fp {

struct ViewerOptions {
    glm::ivec2 windowSize{800, 600};
    ViewerControls controls;  // initial settings (the panel changes them)
    Camera camera;            // the home camera (R returns to it)
    std::string shaderDir;    // empty: the shaders built into the binary; else hot reload from here
    bool ui = true;           // false: no panel (tests, clean captures)
    int bvhThreads = 0;       // threads that build the BVH; 0: every CPU

    // Automation: with frames > 0 the viewer closes itself after that many frames, and when
    // controls.targetSpp > 0 not before that many samples per pixel. It never closes mid-pass: the
    // screenshots hold whole passes (at least one), which may take frames beyond `frames`.
    int frames = 0;
    std::string screenshot;        // written at exit: the rendered image (.png as shown, .exr/.pfm linear)
    std::string windowScreenshot;  // written at exit: the whole window, panel included (.png)
    bool printTiming = false;      // print frame time and throughput at exit
};

// Runs until the window is closed (or the automation ends). Throws fp::Error for what the user can fix
// (no display, no GL 4.1, a shader that does not compile at start).
void runViewer(const Scene& scene, const ViewerOptions& options);

}  // namespace fp
