// The CPU twin's view compiled twice (render/view_pass_cpu.cpp): the AVX2 copy, which runs where
// the processor has AVX2, must give the baseline x86-64 copy's picture to the bit.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "render/view_pass.h"
#include "support/light_transport_setup.h"
#include "support/test_paths.h"

namespace {

// The picture of a fresh CPU renderer, on the AVX2 copy where there is one or on the baseline.
eikon::Image renderCpu(const eikon::Scene& scene, bool avx2) {
    if (avx2)
        unsetenv("EIKON_CPU_AVX2");
    else
        setenv("EIKON_CPU_AVX2", "0", 1);
    eikon::FrameRenderer renderer(scene, eikon::Backend::Cpu);
    eikon::Image image = renderer.render(0);
    unsetenv("EIKON_CPU_AVX2");
    return image;
}

}  // namespace

TEST_CASE("the view's AVX2 copy gives the baseline copy's picture, to the bit", "[view][isa]") {
    if (!eikon::viewCpuHasAvx2())
        WARN(
            "no AVX2 copy here (not x86-64 with AVX2, or a sanitizer build): both renders below "
            "run the baseline copy");
    struct Case {
        std::string name;
        std::string file;
        float ior;     // > 0: the first material's, to bend the rays
        int perSide;   // > 0: photons per side
        float fogTop;  // < 1e9: the first source (a box of fog) ends at this height
    };
    const Case cases[] = {
        {"straight rays: a fog sphere in a box, light volumes", "fog_sphere_spot", 0.0f, 0, 1e9f},
        {"curved rays through a graded sphere", "fog_sphere_spot", 1.3f, 0, 1e9f},
        {"a glass ball's sharp surface, photons, a receiver", "glass_sphere_floor", 0.0f, 24, 0.3f},
        {"a glass mesh's sharp surface, photons, a receiver", "glass_mesh_floor", 0.0f, 24, 0.0f},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        eikon::Scene scene =
            eikon::loadScene(eikon::test::sourcePath("data/scenes/" + c.file + ".json"));
        scene.render.width = 40;
        scene.render.height = 30;
        if (c.ior > 0.0f) scene.materials[0].ior = c.ior;
        if (c.fogTop < 1e9f) scene.sources[0].boxMax.y = c.fogTop;
        if (c.perSide > 0)
            eikon::test::setTransportSetting(scene, "photons", "per_side", c.perSide);
        const eikon::Image avx2 = renderCpu(scene, true);
        const eikon::Image baseline = renderCpu(scene, false);
        REQUIRE(avx2.width == baseline.width);
        REQUIRE(avx2.height == baseline.height);
        CHECK(avx2.pixels == baseline.pixels);
    }
}
