// glad first: GLFW must not pull in a system GL header (GLFW_INCLUDE_NONE).
#include "gl/gl.h"
// clang-format off
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on

#include "gl/glfw_window.h"

#include <algorithm>
#include <utility>

#include "core/error.h"

namespace fp {

namespace {

// GLFW reports the reason for a failure only through its error callback.
std::string lastGlfwError;

extern "C" void recordGlfwError(int, const char* description) {
    lastGlfwError = description ? description : "unknown GLFW error";
}

GlfwWindow* owner(GLFWwindow* window) {
    return static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
}

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
    glfwSetErrorCallback(recordGlfwError);
    lastGlfwError.clear();
    if (!glfwInit())
        throw Error(
            "cannot open a window (" + lastGlfwError +
            "). The viewer needs a display: run it under a virtual one with `xvfb-run -a fragpath view "
            "...`, or render offscreen, without a display or GPU, with `fragpath render ...`");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);  // required for a core context on macOS
    glfwWindowHint(GLFW_DEPTH_BITS, 0);                     // the display pass needs no depth buffer
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        std::string reason = lastGlfwError;
        glfwTerminate();
        throw Error("cannot create a window with an OpenGL 4.1 core context (" + reason +
                    "); `fragpath render ...` renders offscreen without one");
    }
    glfwMakeContextCurrent(window_);
    // Frames are paced by the viewer's render budget, not by the monitor's refresh.
    glfwSwapInterval(0);
    glfwSetWindowUserPointer(window_, this);
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) { owner(w)->scroll_ += dy; });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_PRESS) owner(w)->keyPresses_.push_back(key);
    });
    try {
        loadGlFunctions(reinterpret_cast<GlProcLoader>(glfwGetProcAddress), "GLFW window");
    } catch (...) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw;
    }
}

GlfwWindow::~GlfwWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool GlfwWindow::shouldClose() const {
    return glfwWindowShouldClose(window_);
}

glm::ivec2 GlfwWindow::framebufferSize() const {
    glm::ivec2 size(0);
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

glm::ivec2 GlfwWindow::windowSize() const {
    glm::ivec2 size(0);
    glfwGetWindowSize(window_, &size.x, &size.y);
    return size;
}

void GlfwWindow::pollEvents() {
    glfwPollEvents();
}

void GlfwWindow::waitEvents(double seconds) {
    glfwWaitEventsTimeout(seconds);
}

void GlfwWindow::swapBuffers() {
    glfwSwapBuffers(window_);
}

double GlfwWindow::takeScroll() {
    return std::exchange(scroll_, 0.0);
}

std::vector<int> GlfwWindow::takeKeyPresses() {
    return std::exchange(keyPresses_, {});
}

void GlfwWindow::setCursorCaptured(bool captured) {
    glfwSetInputMode(window_, GLFW_CURSOR, captured ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
}

void GlfwWindow::bindWindowFramebuffer() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void GlfwWindow::finish() {
    glFinish();
}

std::vector<std::uint8_t> GlfwWindow::readBackBuffer(glm::ivec2& size) {
    size = framebufferSize();
    std::vector<std::uint8_t> rows(size_t(size.x) * size_t(size.y) * 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    // GL rows run bottom to top; images run top to bottom.
    std::vector<std::uint8_t> image(rows.size());
    size_t stride = size_t(size.x) * 3;
    for (int y = 0; y < size.y; ++y)
        std::copy_n(&rows[size_t(size.y - 1 - y) * stride], stride, &image[size_t(y) * stride]);
    return image;
}

}  // namespace fp
