#include "render/ui_overlay.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "core/error.h"

namespace eikon {

UiOverlay::UiOverlay(GLFWwindow* window) {
    if (ImGui::GetCurrentContext())
        throw Error("viewer panel", "a panel is open already (ImGui has one context)");
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's folder
    ImGui::StyleColorsDark();
    // The viewer's windows are OpenGL 4.3 core (render/gl_context.h).
    if (!ImGui_ImplGlfw_InitForOpenGL(window, true) ||
        !ImGui_ImplOpenGL3_Init("#version 330 core")) {
        ImGui::DestroyContext();
        throw Error("viewer panel", "Dear ImGui could not start on this window's OpenGL");
    }
}

UiOverlay::~UiOverlay() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void UiOverlay::begin() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void UiOverlay::end() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool UiOverlay::wantsMouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}

bool UiOverlay::wantsKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}

}  // namespace eikon
