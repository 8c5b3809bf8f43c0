// Keyframed smoke sources (core/animation_targets.h targets /simulation/sources/i/..., applied by
// sim/smoke_from_scene.h at every substep's time): the solver asks for the sources at the end
// time of each substep on the one clock, a source moved along x leaves the trail the path
// predicts, and the result does not depend on the thread count.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "core/scene.h"
#include "sim/clock.h"
#include "sim/smoke_from_scene.h"
#include "smoke_test_fields.h"

using namespace eikon;

namespace {

// A 48×12×12 closed box of h = 1/48 with no forces: nothing moves the smoke, so the density is
// exactly what the source injected where it was at each substep. The sphere (radius 0.05 = 2.4
// cells) goes from x = 0.2 at t = 0 to x = 0.8 at t = 1 s, 1.2 cells per frame at 24 fps.
std::string trailScene(const std::string& interpolation) {
    return R"({
  "sources": [{"type": "vdb_sequence", "file": "cache/trail_####.vdb"}],
  "materials": [{"name": "smoke", "scattering": [1, 1, 1]}],
  "time": {"fps": 24, "frame_start": 1, "frame_end": 24},
  "simulation": {
    "domain": {"min": [0, 0, 0], "max": [1, 0.25, 0.25]},
    "resolution": 48,
    "buoyancy_alpha": 0, "buoyancy_beta": 0,
    "sources": [{"type": "sphere", "center": [0.2, 0.125, 0.125], "radius": 0.05,
                 "density_rate": 24}]
  },
  "animation": [{"target": "/simulation/sources/0/center", "interpolation": ")" +
           interpolation + R"(",
                 "times": [0, 1], "values": [[0.2, 0.125, 0.125], [0.8, 0.125, 0.125]]}]
})";
}

struct Moments {
    double mass = 0.0;
    glm::dvec3 centroid{0.0};
    int loX = 1 << 30, hiX = -1;  // cells along x holding smoke
};

Moments moments(const sim::MacGrid& g) {
    Moments m;
    const glm::ivec3 n = g.resolution();
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const double d = g.density(i, j, k);
                if (d <= 0.0) continue;
                m.mass += d;
                m.centroid += d * glm::dvec3(g.domain.cellCenter(i, j, k));
                m.loX = std::min(m.loX, i);
                m.hiX = std::max(m.hiX, i);
            }
    if (m.mass > 0.0) m.centroid /= m.mass;
    return m;
}

}  // namespace

TEST_CASE("the solver updates its sources at the end time of every substep", "[smoke][animation]") {
    sim::SmokeSettings s;
    s.domain = test::closedBox({16, 16, 2}, 1.0f / 16);
    s.fps = 24.0;
    s.firstFrame = 5;
    s.maxCfl = 0.25;
    s.forces.buoyancyAlpha = s.forces.buoyancyBeta = 0.0f;
    sim::SmokeSolver solver(s);
    // A swirl of peak speed 1: CFL 16/24 per frame at h = 1/16, so with maxCfl 0.25 three
    // substeps.
    test::setSwirl(solver.grid(), 1.0f);
    std::vector<double> times;
    solver.setSourceUpdate([&](double t, std::vector<sim::SmokeSource>&) { times.push_back(t); });
    const sim::SmokeStepStats stats = solver.advanceFrame();
    solver.advanceFrame();
    REQUIRE(stats.substeps >= 2);
    REQUIRE(times.size() >= std::size_t(2 * stats.substeps));
    const SimulationClock clock(24.0, 1.0);
    // Frame 5 (the first) runs from the time of frame 4 to that of frame 5, evenly.
    for (int k = 0; k < stats.substeps; ++k)
        CHECK(times[std::size_t(k)] ==
              Approx((4.0 + double(k + 1) / stats.substeps) / 24.0).epsilon(1e-12));
    CHECK(times[std::size_t(stats.substeps - 1)] == clock.timeOfFrame(5));
    CHECK(times.back() == clock.timeOfFrame(6));
    for (std::size_t k = 1; k < times.size(); ++k) CHECK(times[k] > times[k - 1]);
}

TEST_CASE("a keyframed source moving along x leaves the trail its path predicts",
          "[smoke][animation]") {
    const Scene scene = parseScene(trailScene("linear"), "trail.json");
    sim::SmokeSolver solver = sim::smokeSolverFrom(scene);
    const double h = 1.0 / 48.0, r = 0.05, fps = 24.0;
    auto pathX = [](double t) { return 0.2 + 0.6 * std::min(std::max(t, 0.0), 1.0); };
    int substeps = 0;
    for (int f = 1; f <= 24; ++f) substeps += solver.advanceFrame().substeps;
    REQUIRE(substeps == 24);  // nothing moves, so one substep per frame: at t = f/24
    const sim::MacGrid& g = solver.grid();
    const Moments m = moments(g);

    // Each substep adds 24·(1/24) = 1 to every cell whose centre is inside the sphere at its
    // time; the sphere holds the same cells give or take its rasterization, so the centroid is
    // the mean of the centres x(f/24), f = 1..24: 0.2 + 0.6·25/48 = 0.5125. The tolerance is a
    // quarter cell: the cell count of a 2.4-cell sphere varies by ~10 % with its position, which
    // shifts the weighted mean by well under that.
    double meanX = 0.0;
    for (int f = 1; f <= 24; ++f) meanX += pathX(f / fps) / 24.0;
    REQUIRE(meanX == Approx(0.5125));
    CHECK(std::abs(m.centroid.x - meanX) < 0.25 * h);
    WARN("trail centroid x " << m.centroid.x << " (path mean " << meanX << "), cells " << m.loX
                             << ".." << m.hiX);
    // Across the path the sphere is centred between cell centres, so symmetric but for float
    // rounding of a boundary cell's distance (one cell of ~1400 units would move it ~1e-4).
    CHECK(m.centroid.y == Approx(0.125).margin(1e-3));
    CHECK(m.centroid.z == Approx(0.125).margin(1e-3));
    // Extent: the cells nearest the path's axis have centres h/√2 off it (the sphere's centre is
    // between cell centres in y and z), where the sphere's half-width along x is
    // w = √(r² − h²/2). So the first cell holding smoke is the first whose centre is at or right
    // of x(1/24) − w, the last the last at or left of x(1) + w: exact.
    const double w = std::sqrt(r * r - 0.5 * h * h);
    CHECK(m.loX == int(std::ceil((pathX(1 / fps) - w) / h - 0.5)));
    CHECK(m.hiX == int(std::floor((pathX(1.0) + w) / h - 0.5)));
    // No gap: every column of cells along the path holds smoke (the source moves 1.2 cells a
    // substep, less than its radius).
    for (int i = m.loX; i <= m.hiX; ++i) CHECK(g.density(i, 5, 5) + g.density(i, 6, 6) > 0.0f);
    // Mass: one unit per cell per substep inside, 24 substeps of a sphere of ~4/3·π·2.4³ cells.
    const double sphereCells = 4.0 / 3.0 * 3.14159265 * std::pow(r / h, 3.0);
    CHECK(m.mass == Approx(24.0 * sphereCells).epsilon(0.15));
}

TEST_CASE("step interpolation holds the source still until its next key", "[smoke][animation]") {
    // With "step" the sphere stays at x = 0.2 until t = 1: frames 1..23 are bit for bit those of
    // the same scene without the track.
    const Scene scene = parseScene(trailScene("step"), "trail.json");
    Scene still = scene;
    still.animation.clear();
    sim::SmokeSolver stepped = sim::smokeSolverFrom(scene), unmoved = sim::smokeSolverFrom(still);
    for (int f = 1; f <= 23; ++f) {
        stepped.advanceFrame();
        unmoved.advanceFrame();
    }
    CHECK(test::hashState(stepped.grid()) == test::hashState(unmoved.grid()));
    // Frame 24 ends at t = 1, the second key: the sphere jumps to x = 0.8 and injects there.
    stepped.advanceFrame();
    unmoved.advanceFrame();
    const Moments m = moments(stepped.grid());
    CHECK(stepped.sources()[0].shape.center.x == 0.8f);
    CHECK(m.hiX > 36);  // 0.8 + 0.05 reaches cell 40
    CHECK(test::hashState(stepped.grid()) != test::hashState(unmoved.grid()));
}

TEST_CASE("keyframed sources give bit-identical grids on 1 and 2 threads",
          "[smoke][animation][determinism]") {
    // The trail scene with buoyancy and heat, so that the flow moves and needs substeps.
    std::string text = trailScene("catmull_rom");
    text.replace(text.find(R"("buoyancy_alpha": 0, "buoyancy_beta": 0,)"),
                 std::string(R"("buoyancy_alpha": 0, "buoyancy_beta": 0,)").size(),
                 R"("buoyancy_beta": 2, "walls": {"+y": "open"},)");
    text.replace(text.find(R"("density_rate": 24)"), std::string(R"("density_rate": 24)").size(),
                 R"("density_rate": 24, "temperature_rate": 40)");
    const Scene scene = parseScene(text, "trail.json");
    auto run = [&](int threads) {
        tbb::task_arena arena(threads);
        std::uint64_t hash = 0;
        int substeps = 0;
        arena.execute([&] {
            sim::SmokeSolver solver = sim::smokeSolverFrom(scene);
            for (int f = 0; f < 6; ++f) substeps += solver.advanceFrame().substeps;
            hash = test::hashState(solver.grid());
        });
        return std::make_pair(hash, substeps);
    };
    const auto one = run(1), two = run(2);
    CHECK(one.second > 6);  // some frame took more than one substep
    CHECK(one == two);
}
