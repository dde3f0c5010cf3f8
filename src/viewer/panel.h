#pragma once
// The viewer's Dear ImGui panel: statistics, render and display settings, the split view, the camera,
// the heat-map legend, the last shader error and a help section. It edits ViewerControls directly and
// reports one-off requests as PanelActions; it never touches the renderer.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "viewer/viewer_controls.h"

namespace fp {

struct PanelInfo {
    int samples = 0;                // per pixel, completed
    glm::ivec2 accumulation{0};     // accumulation size
    bool reduced = false;           // at the moving resolution
    double samplesPerSecond = 0.0;  // full-image samples
    double pathsPerSecond = 0.0;
    double frameMs = 0.0;
    double denoiseMs = 0.0;  // the last denoising run; 0 if none
    // Real-time mode: the last frame's samples per pixel and its stages to glFinish.
    int realtimeSpp = 0;
    float realtimeScale = 1.0f;  // dynamic resolution: the share of the resolution scale rendered
    double traceMs = 0.0, temporalMs = 0.0, filterMs = 0.0;
    float historyMaxFrames = 0.0f;  // the history-length view's top: maxHistorySamples / spp
    std::string renderer;           // GL_RENDERER, GL_VERSION
    std::string shaderSource;       // "built in" or the hot-reload directory
    std::string shaderError;        // the last compile error, empty when the shaders compile
    std::string message;            // the last screenshot written, etc.
    bool flying = false;
    Camera camera;
    // The scene's point, spot and directional lights, one line each (describePunctualLight); the panel
    // lists them in a "lights" section when there are any.
    std::vector<std::string> lights;
};

struct PanelActions {
    bool resetCamera = false;
    bool toggleFly = false;
    bool screenshot = false;
    bool fitHeatMap = false;
    std::optional<float> fov;                      // degrees
    std::optional<float> aperture, focusDistance;  // the thin lens (Camera)
    bool focusOnTarget = false;                    // back to the target's distance
};

// The panel's window. Its height follows its contents, which it measures as it draws them.
class Panel {
  public:
    // Draws the panel for this frame (between ImGuiLayer::beginFrame and render).
    PanelActions draw(ViewerControls& controls, const PanelInfo& info);

  private:
    float contentHeight_ = 0.0f;  // the window's height for last frame's contents; 0 before the first
    float heightWanted_ = 0.0f;   // read by ImGui's size callback
};

// The controls, one per line, for the panel's help section and `fragpath view --help`.
extern const char* const kViewerControlsHelp;

}  // namespace fp
