#pragma once
// Dear ImGui drawn over a GLFW window's picture: the viewer's panel (apps/view_panel.h). It lives
// in render/ because its OpenGL backend draws with GL and every GL call of Eikon is in render/;
// apps lays out the widgets with <imgui.h> between begin() and end(). The ImGui context is global
// to the process, so there is at most one overlay at a time.
struct GLFWwindow;

namespace eikon {

class UiOverlay {
public:
    // `window`'s context must be current. Chains the window's callbacks installed before it (the
    // viewer's wheel), and gives them back when destroyed. Writes no imgui.ini.
    explicit UiOverlay(GLFWwindow* window);
    ~UiOverlay();
    UiOverlay(const UiOverlay&) = delete;
    UiOverlay& operator=(const UiOverlay&) = delete;

    void begin();  // a new frame of widgets
    void end();    // draws them over what the window's framebuffer holds

    // Whether the last frame's widgets took the mouse or the keyboard (the cursor over the panel,
    // a field being typed in): the viewer's orbit and keys then leave them alone.
    bool wantsMouse() const;
    bool wantsKeyboard() const;
};

}  // namespace eikon
