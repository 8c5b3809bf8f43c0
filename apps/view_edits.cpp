#include "apps/view_edits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "core/error.h"
#include "core/particle_color.h"
#include "render/light_transport_registry.h"

namespace eikon::app {
namespace {

// Whether the viewer edits targets of this kind (see view_edits.h for why not the others).
bool editable(TargetKind kind) {
    switch (kind) {
        case TargetKind::LightPosition:
        case TargetKind::LightDirection:
        case TargetKind::LightColor:
        case TargetKind::LightIntensity:
        case TargetKind::LightCone:
        case TargetKind::LightSoftness:
        case TargetKind::LightAngularDiameter:
        case TargetKind::ClipPoint:
        case TargetKind::ClipNormal:
        case TargetKind::MaterialAbsorption:
        case TargetKind::MaterialScattering:
        case TargetKind::MaterialEmission:
        case TargetKind::MaterialIor:
        case TargetKind::MaterialG:
            return true;
        default:
            return false;
    }
}

// The comma-separated numbers of `text`; false when one is not a finite number.
bool parseNumbers(const std::string& text, std::vector<float>& out) {
    size_t begin = 0;
    while (true) {
        const size_t comma = text.find(',', begin);
        const std::string item = text.substr(begin, comma - begin);
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(v) ||
            std::fabs(v) > 3.4e38)
            return false;
        out.push_back(float(v));
        if (comma == std::string::npos) return true;
        begin = comma + 1;
    }
}

// A float as JSON: the shortest text that reads back as the same float.
std::string jsonNumber(float v) {
    char buf[32];
    for (int digits = 6; digits <= 9; ++digits) {
        std::snprintf(buf, sizeof(buf), "%.*g", digits, double(v));
        if (std::strtof(buf, nullptr) == v) break;
    }
    return buf;
}

}  // namespace

std::optional<AnimationTarget> editableTarget(const Scene& scene, const std::string& pointer,
                                              std::string& why) {
    std::optional<AnimationTarget> target = resolveAnimationTarget(scene, pointer, why);
    if (target && !editable(target->kind)) {
        why =
            "the viewer edits lights, materials and clip planes (the camera is the mouse's; "
            "meshes move by their tracks)";
        target.reset();
    }
    return target;
}

bool ViewEdits::set(const Scene& scene, const std::string& pointer, std::vector<float> value) {
    std::string why;
    const std::optional<AnimationTarget> target = editableTarget(scene, pointer, why);
    if (!target || int(value.size()) != target->width) return false;
    set(ViewEdit{pointer, *target, std::move(value)});
    return true;
}

void ViewEdits::add(const Scene& scene, const std::string& text) {
    const size_t equals = text.find('=');
    if (equals == std::string::npos)
        throw Error("--edit", "'" + text + "' is not POINTER=VALUE (e.g. /lights/0/intensity=2)");
    constexpr const char* kMethodPointer = "/render/light_transport/method";
    if (text.substr(0, equals) == kMethodPointer) {
        setMethod(text.substr(equals + 1));
        return;
    }
    if (text.substr(0, equals) == "/render/light_transport") {
        setTransport(scene, text.substr(equals + 1));
        return;
    }
    // "/materials/<i>/particle_color": a colour map by name.
    const std::string colorKey = "/particle_color", materials = "/materials/";
    const std::string pointer = text.substr(0, equals);
    if (pointer.size() > materials.size() + colorKey.size() && pointer.rfind(materials, 0) == 0 &&
        pointer.compare(pointer.size() - colorKey.size(), colorKey.size(), colorKey) == 0) {
        const std::string index =
            pointer.substr(materials.size(), pointer.size() - materials.size() - colorKey.size());
        if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos ||
            index.size() > 6)
            throw Error("--edit", "'" + pointer + "' in " + scene.path + ": '" + index +
                                      "' is not a material's index");
        setColorMap(scene, std::stoul(index), text.substr(equals + 1));
        return;
    }
    ViewEdit edit;
    edit.pointer = text.substr(0, equals);
    std::string why;
    const std::optional<AnimationTarget> target = editableTarget(scene, edit.pointer, why);
    if (!target) throw Error("--edit", "'" + edit.pointer + "' in " + scene.path + ": " + why);
    edit.target = *target;
    if (!parseNumbers(text.substr(equals + 1), edit.value))
        throw Error("--edit",
                    "'" + text + "': the value is not finite numbers separated by commas");
    if (int(edit.value.size()) != target->width)
        throw Error("--edit", "'" + text + "': " + edit.pointer + " takes " +
                                  std::to_string(target->width) + " number" +
                                  (target->width == 1 ? "" : "s") + ", not " +
                                  std::to_string(edit.value.size()));
    set(std::move(edit));
}

void ViewEdits::set(ViewEdit edit) {
    for (ViewEdit& e : edits_)
        if (e.pointer == edit.pointer) {
            e = std::move(edit);
            return;
        }
    edits_.push_back(std::move(edit));
}

void ViewEdits::setMethod(const std::string& name) {
    std::string names = "auto";
    bool known = name == "auto";
    for (const LightTransportMethod& m : lightTransportMethods()) {
        names += ", " + m.name;
        known = known || m.name == name;
    }
    if (!known)
        throw Error("--edit", "no light-transport method '" + name + "' (there are " + names + ")");
    method_ = name;
}

void ViewEdits::setTransport(const Scene& scene, const std::string& mergePatch) {
    Scene trial = scene;
    apply(trial);  // the section as the edits so far left it
    try {
        patchLightTransport(trial, mergePatch);
        checkLightTransport(trial);
    } catch (const Error& e) {
        throw Error("--edit", e.what());
    } catch (const std::exception& e) {  // nlohmann's parse errors
        throw Error("--edit", "'" + mergePatch + "' is not JSON (" + e.what() + ")");
    }
    transport_ = trial.render.lightTransport;
    method_.clear();  // the section holds the method now
}

void ViewEdits::setColorMap(const Scene& scene, size_t material, const std::string& name) {
    const std::string pointer = "/materials/" + std::to_string(material) + "/particle_color";
    std::string why;
    // The materials the file lists are those whose optics the viewer edits (meshes add theirs).
    if (!editableTarget(scene, "/materials/" + std::to_string(material) + "/absorption", why))
        throw Error("--edit", "'" + pointer + "' in " + scene.path + ": " + why);
    const std::vector<std::string>& names = colorMapNames();
    if (name != "none" && std::find(names.begin(), names.end(), name) == names.end()) {
        std::string known = "none";
        for (const std::string& n : names) known += ", " + n;
        throw Error("--edit", "'" + pointer + "=" + name + "': no colour map '" + name +
                                  "' (there are " + known + ")");
    }
    const ParticleColorSpec& before = scene.materials[material].particleColor;
    ColorMapEdit edit{material, name,
                      before.empty() ? glm::vec2(0.0f, 1.0f) : particleColorRange(before),
                      !before.empty()};
    for (ColorMapEdit& e : colorMaps_)
        if (e.material == material) {
            e = edit;
            return;
        }
    colorMaps_.push_back(edit);
}

void ViewEdits::adopt(const Scene& scene, const ViewEdits& scripted) {
    for (const ViewEdit& e : scripted.edits_) set(e);
    if (!scripted.transport_.empty()) setTransport(scene, scripted.transport_);
    if (!scripted.method_.empty()) setMethod(scripted.method_);
    for (const ColorMapEdit& e : scripted.colorMaps_) setColorMap(scene, e.material, e.map);
}

void ViewEdits::apply(Scene& frame) const {
    for (const ViewEdit& e : edits_) writeAnimationTarget(frame, e.target, e.value.data());
    for (const ColorMapEdit& e : colorMaps_) {
        if (e.material >= frame.materials.size()) continue;
        ParticleColorSpec color;
        if (e.map != "none") {
            color.map = e.map;
            color.range = e.range;
        }
        frame.materials[e.material].particleColor = color;
    }
    if (!transport_.empty()) frame.render.lightTransport = transport_;
    if (!method_.empty()) patchLightTransport(frame, "{\"method\": \"" + method_ + "\"}");
}

std::string ViewEdits::jsonPatch() const {
    std::vector<std::string> ops;
    for (const ViewEdit& e : edits_) {
        std::string value;
        for (size_t k = 0; k < e.value.size(); ++k)
            value += (k ? ", " : "") + jsonNumber(e.value[k]);
        if (e.value.size() > 1) value = "[" + value + "]";
        ops.push_back("{\"op\": \"add\", \"path\": \"" + e.pointer + "\", \"value\": " + value +
                      "}");
    }
    for (const ColorMapEdit& e : colorMaps_) {
        const std::string path = "/materials/" + std::to_string(e.material) + "/particle_color";
        if (e.map != "none")
            ops.push_back("{\"op\": \"add\", \"path\": \"" + path + "\", \"value\": {\"map\": \"" +
                          e.map + "\", \"range\": [" + jsonNumber(e.range.x) + ", " +
                          jsonNumber(e.range.y) + "]}}");
        else if (e.fileHadColor)
            ops.push_back("{\"op\": \"remove\", \"path\": \"" + path + "\"}");
    }
    if (!transport_.empty())
        ops.push_back("{\"op\": \"add\", \"path\": \"/render/light_transport\", \"value\": " +
                      transport_ + "}");
    if (!method_.empty())
        ops.push_back(
            "{\"op\": \"add\", \"path\": \"/render/light_transport/method\", \"value\": \"" +
            method_ + "\"}");
    std::string out = "[";
    for (size_t i = 0; i < ops.size(); ++i) out += (i ? ", " : "") + ops[i];
    return out + "]";
}

}  // namespace eikon::app
