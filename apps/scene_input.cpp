#include "apps/scene_input.h"

#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "render/light_transport_registry.h"

namespace eikon::app {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void parseSize(const std::string& text, RenderSettings& render) {
    int w = 0, h = 0;
    char x = 0;
    if (std::sscanf(text.c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 1 || h < 1 ||
        w > 16384 || h > 16384)
        throw Error("--size", "expected WIDTHxHEIGHT (e.g. 640x480), got '" + text + "'");
    render.width = w;
    render.height = h;
}

}  // namespace

Scene sceneFromInput(const std::string& input, const std::string& outputDir,
                     const std::string& size) {
    Scene scene;
    if (endsWith(input, ".vdb")) {
        scene = defaultSceneForVdb(input);
        scene.output.name = std::filesystem::path(input).stem().string();
    } else {
        scene = loadScene(input);
    }
    // The light-transport section is read by the methods, in render: checked here, before any
    // work, like the rest of the scene.
    checkLightTransport(scene);
    if (!outputDir.empty()) scene.output.directory = outputDir;
    if (!size.empty()) parseSize(size, scene.render);
    return scene;
}

}  // namespace eikon::app
