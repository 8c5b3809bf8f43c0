#pragma once
// Edits of a scene's lights, materials and clip planes made in `eikon view` (scripted by --edit
// today): each is a JSON pointer into the scene as written, as keyframe tracks name their targets
// (core/animation_targets.h), and a value. The viewer writes them into every frame's scene after
// its tracks, so an edit holds while frames play, and the renderer's stage keys decide what
// reruns (a light's intensity: the light transport; a material's n: the ∇n volume, the octree
// and the transport; nothing else). The camera is the mouse's, meshes move by their own tracks
// and simulations, and both are refused here.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/animation_targets.h"
#include "core/scene.h"

namespace eikon::app {

struct ViewEdit {
    std::string pointer;  // "/lights/0/intensity"
    AnimationTarget target;
    std::vector<float> value;  // target.width numbers, as given (writing clamps them)
};

// The target `pointer` names in `scene` if the viewer edits it; nothing, with `why` set, if not.
std::optional<AnimationTarget> editableTarget(const Scene& scene, const std::string& pointer,
                                              std::string& why);

class ViewEdits {
public:
    // Reads "POINTER=V" or "POINTER=V1,V2,V3" against `scene`, and keeps it (replacing an earlier
    // edit of the same pointer). Throws eikon::Error at "--edit" naming the text and the reason:
    // no '=', a pointer that does not resolve or that the viewer does not edit, a count of numbers
    // other than the target's, a number that is not finite.
    void add(const Scene& scene, const std::string& text);
    // Keeps an edit already resolved, replacing an earlier one of the same pointer.
    void set(ViewEdit edit);
    // Keeps `value` for `pointer` (the panel's widgets); false, keeping nothing, for a pointer
    // editableTarget refuses or a value of the wrong count.
    bool set(const Scene& scene, const std::string& pointer, std::vector<float> value);

    // The light-transport method (render/light_transport_registry.h: a registered name or
    // "auto"), its settings sections kept; "--edit /render/light_transport/method=NAME" too.
    // Throws eikon::Error at "--edit" for a name not registered, listing the names.
    void setMethod(const std::string& name);
    const std::string& method() const { return method_; }  // "": the scene's
    // The light-transport settings: `mergePatch` (RFC 7386 JSON, e.g.
    // {"photons": {"per_side": 64}}) merged into `scene`'s render.light_transport with the edits
    // so far, the whole section kept; "--edit /render/light_transport=JSON" too. Throws
    // eikon::Error at "--edit", keeping nothing, for text that is not JSON or settings a method
    // refuses (its pointer and reason).
    void setTransport(const Scene& scene, const std::string& mergePatch);
    const std::string& transport() const { return transport_; }  // "": the scene's

    // Material `material`'s particle colour (core/particle_color.h) by a colour map's name, or
    // "none" for no tint; "--edit /materials/i/particle_color=NAME" too. The map spans the values
    // the material's colour spanned in `scene` (its map's range, or its points' first and last
    // values; [0, 1] where it had none). Throws eikon::Error at "--edit" for a material the scene
    // file does not list or a name that is not a map, listing the maps.
    void setColorMap(const Scene& scene, size_t material, const std::string& name);

    // Keeps every edit of `scripted` (made against `scene`) over this one's.
    void adopt(const Scene& scene, const ViewEdits& scripted);

    // Writes every edit into `frame` (a frame's scene, its tracks evaluated).
    void apply(Scene& frame) const;

    const std::vector<ViewEdit>& edits() const { return edits_; }
    bool empty() const {
        return edits_.empty() && method_.empty() && transport_.empty() && colorMaps_.empty();
    }

    // The edits as a JSON Patch (RFC 6902) of the scene file, on one line: what keeps them
    // (Python's jsonpatch, or by hand). Its operations are "add", which replaces a member that is
    // there and adds one the file left at its default, where "replace" would fail. A method's
    // operation adds /render/light_transport/method, which needs a "light_transport" object
    // in the file's "render" ({} will do); settings add the whole section. A colour map adds the
    // material's "particle_color" as {"map": NAME, "range": [LOW, HIGH]}; "none" removes it
    // where the file had one.
    std::string jsonPatch() const;

private:
    std::vector<ViewEdit> edits_;
    std::string method_;
    std::string transport_;  // the whole render.light_transport section, compact JSON
    struct ColorMapEdit {
        size_t material;
        std::string map;  // a colour map's name, or "none"
        glm::vec2 range;
        bool fileHadColor;  // the scene file gave the material a particle colour
    };
    std::vector<ColorMapEdit> colorMaps_;
};

}  // namespace eikon::app
