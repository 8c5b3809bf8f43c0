#pragma once
// The registered light-transport methods (render/light_transport.h) and how a scene picks one:
// render.light_transport.method names it ("auto", the default: photons where light bends on its
// way and something shows it, light volumes otherwise), and each method reads its own settings
// section, render.light_transport.<name>. Every section is checked, the unused ones too, so a
// typo is an error at its pointer rather than a silent default.
//
// Adding a method: a folder under render/transport/ with its class and settings reader, and one
// line in lightTransportMethods() (docs/architecture.md walks through it).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/json_reader.h"
#include "core/scene.h"
#include "render/light_transport.h"

namespace eikon {

struct LightTransportMethod {
    std::string name;     // as the scene writes it, and the name of its settings section
    std::string summary;  // one line: what it models
    // Reads the method's settings section (null when the scene has none: every default) and
    // makes the method for `device`. Throws eikon::Error at the offending key.
    std::unique_ptr<LightTransport> (*make)(const json::Value* section,
                                            const TransportDevice& device);
    // Named settings `eikon bench methods` runs ("coarse", "default", "fine"): the method's
    // settings section as JSON, from cheap and rough to slow and accurate.
    std::vector<std::pair<std::string, std::string>> benchSettings;
};

// Every registered method, in the order docs and benches list them.
const std::vector<LightTransportMethod>& lightTransportMethods();

// The method the scene asks for, made for `device`, its settings read. Throws eikon::Error
// naming the scene file and the JSON pointer for an unknown method or a bad setting.
std::unique_ptr<LightTransport> makeLightTransport(const Scene& scene,
                                                   const TransportDevice& device);
// The same checks without keeping anything: commands call it before any work.
void checkLightTransport(const Scene& scene);
// The name of the method makeLightTransport makes for this scene ("auto" resolved).
std::string lightTransportName(const Scene& scene);

// makeViewSetup with the part of the scene's method configured (LightTransport::configure), as
// the frame renderer makes it: for stages run outside a renderer (tests, benches).
ViewSetup makeConfiguredViewSetup(const Scene& scene, const RenderVolume& volume,
                                  const CameraFrame& camera,
                                  glm::ivec2 environmentSize = glm::ivec2(0));

// Merges `jsonPatch` (an RFC 7386 merge patch, e.g. {"light_volumes": {"shadows": "marched"}})
// into the scene's render.light_transport: the command line's overrides, and tests.
void patchLightTransport(Scene& scene, const std::string& jsonPatch);

}  // namespace eikon
