#pragma once
// A desktop window whose OpenGL 4.1 core context is the renderer's context (the viewer's GlContext).
// GLFW stays inside this file pair and the viewer's input code; the rest of the program sees a context.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/context.h"

struct GLFWwindow;

namespace fp {

class GlfwWindow : public GlContext {
  public:
    // Opens a window with a `width` x `height` pixel framebuffer and makes its context current.
    // Throws fp::Error when there is no display (naming the ways out: a virtual display with xvfb-run,
    // or the offscreen `fragpath render`) or no OpenGL 4.1 core context.
    GlfwWindow(int width, int height, const std::string& title);
    ~GlfwWindow() override;
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    // For input polling (glfwGetKey...) and Dear ImGui's GLFW backend.
    GLFWwindow* handle() const { return window_; }

    bool shouldClose() const;
    glm::ivec2 framebufferSize() const;  // pixels, what the display pass draws into
    glm::ivec2 windowSize() const;       // screen coordinates, what cursor positions are measured in

    void pollEvents();
    // Sleeps until an event arrives or `seconds` pass: for frames with nothing to render.
    void waitEvents(double seconds);
    void swapBuffers();

    // Wheel motion and key presses since the last call. GLFW offers no polling for either; callbacks
    // collect them (installed before Dear ImGui's, which chains to them).
    double takeScroll();
    std::vector<int> takeKeyPresses();  // GLFW key codes, in order
    // Fly mode hides the cursor and reports unbounded motion.
    void setCursorCaptured(bool captured);

    // Makes the window the target of the next draw (the renderer leaves its own framebuffers bound).
    void bindWindowFramebuffer();
    // Waits until the GPU has finished all queued work, so that frame timing measures real work.
    void finish();
    // The back buffer as RGB8, top row first: a capture of the whole window, overlays included.
    std::vector<std::uint8_t> readBackBuffer(glm::ivec2& size);

  private:
    GLFWwindow* window_ = nullptr;
    double scroll_ = 0.0;
    std::vector<int> keyPresses_;
};

}  // namespace fp
