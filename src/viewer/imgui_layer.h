#pragma once
// Dear ImGui on the viewer's window: context, GLFW input backend and OpenGL 3 draw backend, for the
// lifetime of one object. ImGui draws with its own GL calls (it saves and restores the GL state it
// touches), after the display pass and before the buffer swap.
struct GLFWwindow;

namespace fp {

class ImGuiLayer {
  public:
    // Install after the window's own callbacks: ImGui's GLFW backend chains to them.
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void beginFrame();
    void render();     // draws the frame's widgets into the bound framebuffer
    void skipFrame();  // ends the frame without drawing (the window keeps its last picture)

    // Whether the cursor is over a widget (or dragging one) and a text field has focus, as of
    // beginFrame(): the camera ignores such input.
    bool wantsMouse() const;
    bool wantsKeyboard() const;
    // Fly mode captures the cursor for mouse look: the panel must not react to it meanwhile.
    void setMouseEnabled(bool enabled);
};

}  // namespace fp
