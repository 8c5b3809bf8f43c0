#pragma once
// Scenes for tests that hold a shortcut of the CPU twin's view to the picture without it, to the
// bit (tests/render/test_empty_space.cpp, test_view_isa.cpp, test_constant_bricks.cpp): a fresh CPU
// renderer's picture with an environment switch set or unset, and the scenes that cover straight
// and curved rays, sharp surfaces, photons and receivers.
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "support/light_transport_setup.h"
#include "support/test_paths.h"

namespace eikon::test {

// The picture of a fresh CPU renderer with environment variable `name` set to `value`, or unset
// where value is null; unset again afterwards.
inline Image renderCpuWithSwitch(const Scene& scene, const char* name, const char* value) {
    if (value)
        setenv(name, value, 1);
    else
        unsetenv(name);
    FrameRenderer renderer(scene, Backend::Cpu);
    Image image = renderer.render(0);
    unsetenv(name);
    return image;
}

// Whether the pictures of `scene` with switch `name` set to "0" (the shortcut off) and unset are
// the same bytes.
inline bool switchKeepsEveryByte(const Scene& scene, const char* name) {
    const Image off = renderCpuWithSwitch(scene, name, "0");
    const Image on = renderCpuWithSwitch(scene, name, nullptr);
    return off.width == on.width && off.height == on.height &&
           std::memcmp(off.pixels.data(), on.pixels.data(),
                       off.pixels.size() * sizeof(off.pixels[0])) == 0;
}

struct ViewVariantCase {
    std::string name;  // what it covers
    std::string file;  // data/scenes/<file>.json
    float ior;         // > 0: the first material's, to bend the rays
    int perSide;       // > 0: photons per side
    float fogTop;      // < 1e9: the first source (a box of fog) ends at this height
    float radius = 0;  // > 0: the first source's (a sphere's), its falloff a third of it
};

inline std::vector<ViewVariantCase> viewVariantCases() {
    return {
        {"straight rays: a fog sphere in a box, light volumes", "fog_sphere_spot", 0.0f, 0, 1e9f},
        // Rays cross long runs of empty bricks, which straight rays skip whole.
        {"straight rays: a small fog sphere in empty space", "fog_sphere_spot", 0.0f, 0, 1e9f,
         0.3f},
        {"curved rays through a graded sphere", "fog_sphere_spot", 1.3f, 0, 1e9f},
        // The ball sits half in a layer of fog, half in empty space; its rays reflect, and the
        // camera's rays end on the floor.
        {"a glass ball's sharp surface, photons, a receiver", "glass_sphere_floor", 0.0f, 24, 0.3f},
        {"a glass mesh's sharp surface, photons, a receiver", "glass_mesh_floor", 0.0f, 24, 0.0f},
        {"dispersion: three rays a pixel, each channel's own gradient", "crystal_dispersion", 0.0f,
         0, 1e9f},
    };
}

// The case's scene at 40×30.
inline Scene loadViewVariantScene(const ViewVariantCase& c) {
    Scene scene = loadScene(sourcePath("data/scenes/" + c.file + ".json"));
    scene.render.width = 40;
    scene.render.height = 30;
    if (c.ior > 0.0f) scene.materials[0].ior = c.ior;
    if (c.fogTop < 1e9f) scene.sources[0].boxMax.y = c.fogTop;
    if (c.radius > 0.0f) {
        scene.sources[0].radius = c.radius;
        scene.sources[0].falloff = c.radius / 3.0f;
    }
    if (c.perSide > 0) setTransportSetting(scene, "photons", "per_side", c.perSide);
    return scene;
}

// The names of the cases whose pictures switch `name` set to "0" changes (switchKeepsEveryByte);
// empty where it keeps every byte of every case.
inline std::vector<std::string> casesChangedBySwitch(const char* name) {
    std::vector<std::string> changed;
    for (const ViewVariantCase& c : viewVariantCases())
        if (!switchKeepsEveryByte(loadViewVariantScene(c), name)) changed.push_back(c.name);
    return changed;
}

}  // namespace eikon::test
