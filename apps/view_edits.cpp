#include "apps/view_edits.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "core/error.h"
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

void ViewEdits::apply(Scene& frame) const {
    for (const ViewEdit& e : edits_) writeAnimationTarget(frame, e.target, e.value.data());
    if (!transport_.empty()) frame.render.lightTransport = transport_;
    if (!method_.empty()) patchLightTransport(frame, "{\"method\": \"" + method_ + "\"}");
}

std::string ViewEdits::jsonPatch() const {
    std::string out = "[";
    for (size_t i = 0; i < edits_.size(); ++i) {
        const ViewEdit& e = edits_[i];
        std::string value;
        for (size_t k = 0; k < e.value.size(); ++k)
            value += (k ? ", " : "") + jsonNumber(e.value[k]);
        if (e.value.size() > 1) value = "[" + value + "]";
        out += std::string(i ? ", " : "") + "{\"op\": \"add\", \"path\": \"" + e.pointer +
               "\", \"value\": " + value + "}";
    }
    if (!transport_.empty())
        out += std::string(edits_.empty() ? "" : ", ") +
               "{\"op\": \"add\", \"path\": \"/render/light_transport\", \"value\": " + transport_ +
               "}";
    if (!method_.empty())
        out += std::string(edits_.empty() && transport_.empty() ? "" : ", ") +
               "{\"op\": \"add\", \"path\": \"/render/light_transport/method\", \"value\": \"" +
               method_ + "\"}";
    return out + "]";
}

}  // namespace eikon::app
