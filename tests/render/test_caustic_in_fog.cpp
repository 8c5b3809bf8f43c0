// Issue 15's hard case "a caustic focus inside the fog": a sharp (falloff 0) n = 1.5 glass ball
// whose caustic, from the marginal rays' focus just behind it to the paraxial focus
// nR / (2(n − 1)) = 0.45 below its centre, lies inside a scattering fog that fills the lower part
// of the volume, under straight and slanted light. (A ball of n ≥ 2 focuses inside
// itself: the n = 2.4 and 3.0 balls are test_photons.cpp's hard cases.) The photons that converge
// there must stay bounded and NaN-free, the energy must balance, the fluence must peak at the focus
// inside the fog, and the picture must be finite. CPU twin (the GPU's photons equal it:
// test_photons_gpu.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "support/light_transport_setup.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

constexpr int kRes = 48;  // issue 3's test budget, 64³ at most

// The scene: fog (σs 0.5, σa 0.1) below y = 0.38, the ball R 0.3 at y = 0.7 (its bottom at 0.4,
// its paraxial focus at 0.25), a directional light along `d`.
Scene causticInFog(const std::string& dir, glm::vec3 d) {
    const std::string path = dir + "/caustic_in_fog.json";
    std::ofstream(path) << R"({
  "volume": { "bounds": { "min": [-1, -1, -1], "max": [1, 1, 1] }, "resolution": )"
                        << kRes << R"( },
  "sources": [
    { "type": "box", "field": "density", "min": [-1, -1, -1], "max": [1, 0.38, 1], "value": 1 },
    { "type": "sphere", "field": "n", "center": [0, 0.7, 0], "radius": 0.3, "value": 1 }
  ],
  "materials": [
    { "name": "fog", "field": "density", "absorption": [0.1, 0.1, 0.1],
      "scattering": [0.5, 0.5, 0.5] },
    { "name": "glass", "field": "n", "ior": 1.5 }
  ],
  "lights": [ { "type": "directional", "direction": [)"
                        << d.x << ", " << d.y << ", " << d.z << R"(] } ],
  "camera": { "position": [0, 0.2, 4], "look_at": [0, 0, 0] },
  "render": { "width": 32, "height": 24,
              "light_transport": { "method": "photons", "photons": { "per_side": 96 } } }
})";
    return loadScene(path);
}

size_t voxelIndex(int i, int j, int k) {
    return (size_t(k) * kRes + size_t(j)) * kRes + size_t(i);
}

}  // namespace

TEST_CASE("issue 15's hard case: a sharp glass ball's caustic focus inside scattering fog",
          "[photons][lens]") {
    const std::string dir = test::scratchDir("caustic_in_fog");
    for (glm::vec3 d : {glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.3f, -1.0f, 0.2f)}) {
        INFO("light along " << d.x << " " << d.y << " " << d.z);
        FrameRenderer renderer(causticInFog(dir, glm::normalize(d)), Backend::Cpu);
        const Image image = renderer.render(0);
        bool finite = true;
        for (const glm::vec4& p : image.pixels)
            finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        CHECK(finite);

        const PhotonVolumes v = test::photonVolumesOf(renderer);
        REQUIRE(v.photonsTraced > 0);
        // Cut only by the stop rule: at most its fraction (checkBoundedAndBalanced,
        // test_photons.cpp, says why a few may be).
        CHECK(double(v.photonsCut) < std::ceil(1e-3 * double(v.photonsTraced)));
        bool volumesFinite = true;
        for (const glm::vec4& r : v.radiance) volumesFinite = volumesFinite && std::isfinite(r.y);
        CHECK(volumesFinite);
        const std::optional<EnergyBalance> e = renderer.lightTransport().energy();
        REQUIRE(e);
        const glm::dvec3 rest = e->accounted();
        for (int c = 0; c < 3; ++c) CHECK(std::abs(rest[c] / e->emitted[c] - 1.0) < 1e-6);

        if (d.x != 0.0f) continue;
        // Straight light: inside the fog, between the marginal rays' focus at the ball and the
        // paraxial focus (y 0.25 to 0.38), the fluence on the axis is far above the fog's
        // unfocused fluence at the same depth 0.6 units off the axis (measured 17-24×). (Where on
        // the axis it peaks is issue 15's item 2, the density estimate past a focus: measured at
        // the ball's back surface, falling monotonically into the fog.)
        const int axis = kRes / 2;
        const double h = 2.0 / kRes;
        for (int j = 0; j < kRes; ++j) {
            const double y = -1.0 + (j + 0.5) * h;
            if (y < 0.25 || y > 0.38) continue;
            const double focused = v.radiance[voxelIndex(axis, j, axis)].y;
            const double unfocused = v.radiance[voxelIndex(axis + int(0.6 / h), j, axis)].y;
            INFO("y = " << y << ": the axis's fluence " << focused / unfocused
                        << "x the fluence 0.6 off it");
            CHECK(focused > 5.0 * unfocused);
        }
    }
}
