#include "apps/view_panel.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/error.h"
#include "core/particle_color.h"
#include "render/light_transport_registry.h"

namespace eikon::app {
namespace {

const char* lightTypeName(LightType type) {
    switch (type) {
        case LightType::Point:
            return "point";
        case LightType::Spot:
            return "spot";
        default:
            return "directional";
    }
}

// One widget's edit: the panel shows the value of the scene on screen and keeps what the user
// sets it to under `pointer`, if the viewer edits it there (editableTarget).
class Editor {
public:
    Editor(const Scene& shown, ViewEdits& edits, PanelRequests& requests)
        : shown_(shown), edits_(edits), requests_(requests) {}

    bool editable(const std::string& pointer) const {
        std::string why;
        return editableTarget(shown_, pointer, why).has_value();
    }
    void number(const char* label, const std::string& pointer, float value, float speed, float lo,
                float hi) {
        if (!editable(pointer)) return;
        if (ImGui::DragFloat(label, &value, speed, lo, hi, "%.4g")) keep(pointer, {value});
    }
    void vector(const char* label, const std::string& pointer, glm::vec3 value, float speed,
                float lo = 0.0f, float hi = 0.0f) {
        if (!editable(pointer)) return;
        if (ImGui::DragFloat3(label, &value.x, speed, lo, hi, "%.4g"))
            keep(pointer, {value.x, value.y, value.z});
    }
    void color(const char* label, const std::string& pointer, glm::vec3 value) {
        if (!editable(pointer)) return;
        if (ImGui::ColorEdit3(label, &value.x, ImGuiColorEditFlags_Float))
            keep(pointer, {value.x, value.y, value.z});
    }

    // Material `material`'s particle colour: "none" or a colour map by name; a point function
    // shows as "points" until a map replaces it.
    void colorMap(size_t material, const ParticleColorSpec& shownColor) {
        const std::string current = !shownColor.map.empty()      ? shownColor.map
                                    : !shownColor.points.empty() ? "points"
                                                                 : "none";
        if (!ImGui::BeginCombo("particle colour", current.c_str())) return;
        std::vector<std::string> names = {"none"};
        for (const std::string& name : colorMapNames()) names.push_back(name);
        for (const std::string& name : names)
            if (ImGui::Selectable(name.c_str(), name == current) && name != current) {
                edits_.setColorMap(shown_, material, name);
                requests_.edited = true;
            }
        ImGui::EndCombo();
    }

private:
    void keep(const std::string& pointer, std::vector<float> value) {
        if (edits_.set(shown_, pointer, std::move(value))) requests_.edited = true;
    }
    const Scene& shown_;
    ViewEdits& edits_;
    PanelRequests& requests_;
};

void lightRows(const Scene& shown, Editor& editor) {
    for (size_t i = 0; i < shown.lights.size(); ++i) {
        const LightSpec& light = shown.lights[i];
        const std::string base = "/lights/" + std::to_string(i) + "/";
        const std::string title = "light " + std::to_string(i) + " (" + lightTypeName(light.type) +
                                  ")##light" + std::to_string(i);
        if (!ImGui::TreeNodeEx(title.c_str(), i == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0))
            continue;
        editor.color("colour", base + "color", light.color);
        editor.number("intensity", base + "intensity", light.intensity, 0.05f, 0.0f, 1e6f);
        editor.vector("position", base + "position", light.position, 0.01f);
        editor.vector("direction", base + "direction", light.direction, 0.01f, -1.0f, 1.0f);
        editor.number("cone (deg)", base + "cone_angle_deg", light.coneAngleDeg, 0.1f, 0.1f, 89.0f);
        editor.number("cone edge (deg)", base + "cone_softness_deg", light.coneSoftnessDeg, 0.1f,
                      0.0f, 89.0f);
        editor.number("disc (deg)", base + "angular_diameter_deg", light.angularDiameterDeg, 0.05f,
                      0.0f, kMaxAngularDiameterDeg);
        ImGui::TreePop();
    }
}

// The optics of material `m` under the pointers `base` + key: a scene's own material
// (/materials/i/) or a mesh's (/meshes/i/, whose n lives in the material "<mesh>.n").
void opticsRows(const MaterialSpec& m, const MaterialSpec* index, const std::string& base,
                Editor& editor) {
    if (index) editor.number("n", base + "ior", index->ior, 0.002f, 1.0f, 4.0f);
    editor.vector("absorption", base + "absorption", m.absorption, 0.01f, 0.0f, 1e4f);
    editor.vector("scattering", base + "scattering", m.scattering, 0.01f, 0.0f, 1e4f);
    editor.vector("emission", base + "emission", m.emission, 0.01f, 0.0f, 1e4f);
    editor.number("g", base + "g", m.g, 0.005f, -0.99f, 0.99f);
}

const MaterialSpec* materialNamed(const Scene& scene, const std::string& name) {
    for (const MaterialSpec& m : scene.materials)
        if (m.name == name) return &m;
    return nullptr;
}

void materialRows(const Scene& shown, Editor& editor) {
    size_t own = 0;  // the scene's own materials come first, as /materials/i/ counts them
    while (own < shown.materials.size() &&
           editor.editable("/materials/" + std::to_string(own) + "/absorption"))
        ++own;
    for (size_t i = 0; i < own; ++i) {
        const MaterialSpec& m = shown.materials[i];
        const std::string title = "material " + m.name + "##material" + std::to_string(i);
        if (!ImGui::TreeNode(title.c_str())) continue;
        opticsRows(m, &m, "/materials/" + std::to_string(i) + "/", editor);
        editor.colorMap(i, m.particleColor);
        ImGui::TreePop();
    }
    for (size_t i = 0; i < shown.meshes.size(); ++i) {
        const std::string& name = shown.meshes[i].name;
        const MaterialSpec* optics = materialNamed(shown, name);
        const MaterialSpec* index = materialNamed(shown, name + ".n");
        if (!optics && !index) continue;
        const std::string title = "mesh " + name + "##mesh" + std::to_string(i);
        if (!ImGui::TreeNode(title.c_str())) continue;
        const std::string base = "/meshes/" + std::to_string(i) + "/";
        if (index) editor.number("n", base + "ior", index->ior, 0.002f, 1.0f, 4.0f);
        if (optics) {
            editor.vector("absorption", base + "absorption", optics->absorption, 0.01f, 0.0f, 1e4f);
            editor.vector("scattering", base + "scattering", optics->scattering, 0.01f, 0.0f, 1e4f);
            editor.vector("emission", base + "emission", optics->emission, 0.01f, 0.0f, 1e4f);
        }
        ImGui::TreePop();
    }
}

// The method combo: "auto" and every registered method; the scene's choice shows first.
void methodRow(const Scene& shown, ViewEdits& edits, PanelRequests& requests) {
    const std::string current = lightTransportName(shown);
    if (!ImGui::BeginCombo("light transport", current.c_str())) return;
    std::vector<std::string> names{"auto"};
    for (const LightTransportMethod& m : lightTransportMethods()) names.push_back(m.name);
    for (const std::string& name : names)
        if (ImGui::Selectable(name.c_str(), name == current) && name != current) {
            edits.setMethod(name);
            requests.edited = true;
        }
    ImGui::EndCombo();
}

// The method's settings as the scene's render.light_transport JSON, typed and applied; settings a
// method refuses are shown in red and change nothing.
void transportSettingsRows(const Scene& shown, ViewEdits& edits, PanelMemory& memory,
                           PanelRequests& requests) {
    if (!ImGui::CollapsingHeader("light transport settings (JSON)")) return;
    if (memory.transportText.empty()) memory.transportText = shown.render.lightTransport;
    ImGui::InputTextMultiline("##transport", &memory.transportText, ImVec2(-1.0f, 60.0f));
    if (ImGui::Button("Apply")) {
        try {
            edits.setTransport(shown, memory.transportText);
            memory.transportError.clear();
            requests.edited = true;
        } catch (const Error& e) {
            memory.transportError = e.reason();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("As on screen")) memory.transportText = shown.render.lightTransport;
    if (!memory.transportError.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", memory.transportError.c_str());
}

void figureRows(const PanelFigures& f, PanelRequests& requests) {
    if (f.scale == 1)
        ImGui::Text("frame %d, full size, %.0f ms (%.1f fps)", f.frame, f.frameMs,
                    f.frameMs > 0 ? 1000.0 / f.frameMs : 0.0);
    else
        ImGui::Text("frame %d, 1/%d size, %.0f ms (%.1f fps)", f.frame, f.scale, f.frameMs,
                    f.frameMs > 0 ? 1000.0 / f.frameMs : 0.0);
    // The preview's budget (render/preview_budget.h): 0 keeps the preview scale where it is.
    float budget = float(f.frameBudgetMs);
    if (ImGui::SliderFloat("frame budget ms", &budget, 0.0f, 1000.0f, "%.0f",
                           ImGuiSliderFlags_Logarithmic))
        requests.frameBudgetMs = std::max(0.0, double(budget));
    if (ImGui::Button(f.playing ? "Pause" : "Play")) requests.togglePlay = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset frames")) requests.reset = true;
    if (!ImGui::CollapsingHeader("stages (ms)")) return;
    for (const StageTime& s : f.stages)
        ImGui::Text("%-10s %8.1f", s.name.c_str(), s.gpuMs > 0 ? s.gpuMs : s.cpuMs);
}

}  // namespace

PanelRequests drawViewPanel(const Scene& shown, ViewEdits& edits, const PanelFigures& figures,
                            PanelMemory& memory) {
    PanelRequests requests;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(360, 0), ImVec2(360, 1e6f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    // Its height follows what is open, so that nothing hides below a scroll bar.
    if (!ImGui::Begin("eikon (Tab hides)", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return requests;
    }
    ImGui::PushItemWidth(215.0f);  // and the labels to its right
    figureRows(figures, requests);
    methodRow(shown, edits, requests);
    transportSettingsRows(shown, edits, memory, requests);
    Editor editor(shown, edits, requests);
    if (ImGui::CollapsingHeader("lights", ImGuiTreeNodeFlags_DefaultOpen)) lightRows(shown, editor);
    if (ImGui::CollapsingHeader("materials")) materialRows(shown, editor);
    if (!edits.empty() && ImGui::Button("Copy as JSON")) {
        const std::string patch = edits.jsonPatch();
        ImGui::SetClipboardText(patch.c_str());
        std::printf("the edits as a JSON Patch of the scene (on the clipboard): %s\n",
                    patch.c_str());
    }
    ImGui::PopItemWidth();
    ImGui::End();
    return requests;
}

}  // namespace eikon::app
