// A scene's "simulation" section becomes a solver with its settings, sources and obstacles.
#include <catch2/catch.hpp>

#include "core/scene.h"
#include "sim/smoke_from_scene.h"

using namespace eikon;

namespace {

const char* const kScene = R"({
  "sources": [{"type": "vdb_sequence", "file": "cache/smoke_####.vdb"}],
  "materials": [{"name": "smoke", "scattering": [1, 1, 1]}],
  "time": {"fps": 12},
  "simulation": {
    "domain": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]},
    "resolution": 16,
    "walls": {"+y": "open"},
    "advection": "semi_lagrangian", "limiter": "none",
    "vorticity": 1, "wind": [0.1, 0, 0],
    "pressure": {"tolerance": 1e-4, "max_iterations": 300},
    "sources": [{"type": "sphere", "center": [0, 0.2, 0], "radius": 0.15,
                 "density_rate": 5, "temperature_rate": 20}],
    "obstacles": [{"type": "box", "min": [-0.2, 0.6, -0.2], "max": [0.2, 0.7, 0.2]}]
  }
})";

}  // namespace

TEST_CASE("a solver built from a parsed scene has its settings and steps a frame",
          "[smoke][scene]") {
    const Scene scene = parseScene(kScene, "plume.json");
    REQUIRE(scene.simulations.size() == 1);
    sim::SmokeSolver solver = sim::smokeSolverFrom(scene.simulations.at(0), scene.time.fps);

    const sim::SmokeSettings& s = solver.settings();
    CHECK(s.fps == 12.0);
    CHECK(s.domain.resolution == glm::ivec3(16));
    CHECK(s.domain.voxelSize == Approx(1.0f / 16));
    CHECK(s.domain.origin == glm::vec3(-0.5f, 0.0f, -0.5f));
    CHECK(s.domain.wall(1, true) == sim::Wall::Open);
    CHECK(s.domain.wall(1, false) == sim::Wall::Closed);
    CHECK(s.advection.scheme == sim::AdvectionScheme::SemiLagrangian);
    CHECK(s.advection.limiter == sim::Limiter::None);
    CHECK(s.forces.vorticity == 1.0f);
    CHECK(s.forces.wind == glm::vec3(0.1f, 0, 0));
    CHECK(s.pressure.tolerance == 1e-4);
    CHECK(s.pressure.maxIterations == 300);

    // The obstacle box covers cells with centres at y in [0.6, 0.7]: only j = 10 (centre 0.656).
    const sim::MacGrid& g = solver.grid();
    CHECK(g.isSolid(8, 10, 8));
    CHECK_FALSE(g.isSolid(8, 2, 8));

    const sim::SmokeStepStats stats = solver.advanceFrame();
    CHECK(stats.substeps >= 1);
    CHECK(solver.frame() == 1);
    // The source injected density and heat at its centre, none inside the obstacle.
    CHECK(g.density(8, 3, 8) > 0.0f);
    CHECK(g.temperature(8, 3, 8) > 0.0f);
    CHECK(g.density(8, 10, 8) == 0.0f);
}
