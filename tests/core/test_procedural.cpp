// Procedural sources (core/procedural.h): the profiles against their formulas at the voxel
// centres (the Luneburg index, a linear ramp), a sharp edge as the voxel's coverage, the rounded
// box's surface, clip boxes that split one
// shape without gap or overlap, and the parser's keys for them with their mistakes.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <openvdb/tools/Interpolation.h>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/procedural.h"
#include "core/resample.h"
#include "core/scene.h"
#include "core/scene_sources.h"
#include "core/vdb_import.h"
#include "support/scene_builders.h"

using namespace eikon;
using Catch::Matchers::Contains;

namespace {

// The grids store floats: a value computed in double is off by at most half an ulp of ~1.
constexpr double kFloatRounding = 1e-7;

// Every voxel centre of `grid` in the box [lo, hi], with the value stored there.
template <typename F>
void forEachCentre(const openvdb::FloatGrid& grid, glm::vec3 lo, glm::vec3 hi, const F& f) {
    const double h = grid.voxelSize().x();
    const glm::ivec3 i0 = glm::ivec3(glm::floor(glm::dvec3(lo) / h));
    const glm::ivec3 i1 = glm::ivec3(glm::ceil(glm::dvec3(hi) / h));
    auto acc = grid.getConstAccessor();
    for (int k = i0.z; k <= i1.z; ++k)
        for (int j = i0.y; j <= i1.y; ++j)
            for (int i = i0.x; i <= i1.x; ++i) {
                const openvdb::Vec3d w = grid.transform().indexToWorld(openvdb::Coord(i, j, k));
                f(glm::dvec3(w.x(), w.y(), w.z()), double(acc.getValue(openvdb::Coord(i, j, k))));
            }
}

SourceSpec luneburg(glm::vec3 centre, float radius, float voxel) {
    SourceSpec s = test::sphereSource("n", centre, radius, 1.0f, 0.0f, voxel);
    s.profile = SourceProfile::Luneburg;
    return s;
}

struct Failure {
    std::string where;
    std::string reason;
};

Failure failureOf(const std::string& text) {
    try {
        parseScene(text, "lens.json");
    } catch (const Error& e) {
        return {e.where(), e.reason()};
    }
    FAIL("expected an eikon::Error for: " << text);
    return {};
}

// A scene with one source (JSON object text) and one glass material reading `field`.
std::string sceneWithSource(const std::string& source, const std::string& field = "n") {
    return R"({"sources": [)" + source + R"(], "materials": [{"name": "glass", "field": ")" +
           field + R"(", "ior": 2}]})";
}

}  // namespace

TEST_CASE("luneburg profile: n = sqrt(2 - (r/R)^2) at every voxel centre with ior 2",
          "[procedural]") {
    ensureOpenVdbInitialized();
    const glm::vec3 centre(0.1f, -0.2f, 0.05f);
    const float radius = 0.8f;
    const SourceSpec src = luneburg(centre, radius, 0.05f);
    const auto grid = makeProceduralField(src);
    int inside = 0;
    double worst = 0.0;
    forEachCentre(*grid, centre - 1.0f, centre + 1.0f, [&](glm::dvec3 p, double f) {
        const double s = glm::length(p - glm::dvec3(centre)) / double(radius);
        // A material of ior 2 makes n = 1 + f.
        const double n = 1.0 + f;
        const double want = s <= 1.0 ? std::sqrt(2.0 - s * s) : 1.0;
        worst = std::max(worst, std::abs(n - want));
        if (s <= 1.0) ++inside;
    });
    INFO(inside << " voxel centres inside, worst |n - sqrt(2 - (r/R)^2)| " << worst);
    CHECK(inside > 8000);  // (4/3)π 16³
    CHECK(worst <= kFloatRounding);
    CHECK(luneburgExcessIndex(0.0, 2.0) == Approx(std::sqrt(2.0) - 1.0).epsilon(1e-15));
    CHECK(luneburgExcessIndex(2.0, 2.0) == 0.0);
    CHECK(luneburgExcessIndex(3.0, 2.0) == 0.0);
    CHECK(luneburgExcessIndex(1.0, 2.0) == Approx(std::sqrt(1.75) - 1.0).epsilon(1e-15));

    // `value` scales the profile; through a scene's sources and a resample on the grid's own
    // voxel centres the values arrive unchanged.
    Scene scene;
    scene.path = "lens.json";
    SourceSpec half = src;
    half.value = 0.5f;
    half.jsonPath = "/sources/0";
    scene.sources.push_back(half);
    MaterialSpec glass;
    glass.name = "glass";
    glass.field = "n";
    glass.ior = 3.0f;  // 1 + 0.5 · (3 − 1) · excess = the same lens
    scene.materials.push_back(glass);
    FieldRegistry fields;
    SceneSources(scene).loadFrame(0, fields);
    const RenderVolume volume{{glm::vec3(-0.8f, -1.0f, -0.8f), glm::vec3(1.0f, 0.8f, 1.0f)},
                              glm::ivec3(36)};
    const DenseGrid dense = resampleToDense(fields.get("n"), volume);
    double worstDense = 0.0;
    for (int k = 0; k < 36; ++k)
        for (int j = 0; j < 36; ++j)
            for (int i = 0; i < 36; ++i) {
                const glm::dvec3 p(volume.voxelCenter(i, j, k));
                const double n = 1.0 + double(dense.at(i, j, k)) * (glass.ior - 1.0);
                const double s = glm::length(p - glm::dvec3(centre)) / double(radius);
                worstDense =
                    std::max(worstDense, std::abs(n - (s <= 1.0 ? std::sqrt(2.0 - s * s) : 1.0)));
            }
    INFO("resampled: worst |n - formula| " << worstDense);
    // Sample positions rounded to float: a few ulps of the gradient (≤ 1.8 per unit) times 1e-7.
    CHECK(worstDense < 1e-6);
    CHECK_NOTHROW(checkRefractiveIndex(scene, fields, {{"n", dense}}));
}

TEST_CASE("ramp: linear along its axis inside, clamped then fading outside", "[procedural]") {
    ensureOpenVdbInitialized();
    SourceSpec slab = test::boxSource("n", glm::vec3(-1.0f, -0.5f, -1.0f),
                                      glm::vec3(1.0f, 0.5f, 1.0f), 0.0f, 0.2f, 0.05f);
    slab.profile = SourceProfile::Ramp;
    slab.rampAxis = 1;
    slab.rampFrom = 0.1f;
    slab.rampTo = 0.4f;
    const auto grid = makeProceduralField(slab);
    // Distance outside the slab (0 inside).
    auto outside = [](glm::dvec3 p) {
        return glm::length(glm::max(glm::abs(p) - glm::dvec3(1.0, 0.5, 1.0), 0.0));
    };
    auto formula = [&](glm::dvec3 p) {
        const double t = std::clamp(p.y + 0.5, 0.0, 1.0);
        const double inside = 0.1 + 0.3 * t;
        const double d = outside(p);
        return d < 0.2 ? inside * (1.0 - d / 0.2) : 0.0;
    };
    double worst = 0.0;
    int samples = 0;
    forEachCentre(*grid, glm::vec3(-1.4f, -0.9f, -1.4f), glm::vec3(1.4f, 0.9f, 1.4f),
                  [&](glm::dvec3 p, double f) {
                      // Within half a voxel of the surface or of the falloff's end, the voxel
                      // averages the ramp across its kink (tested below); elsewhere the average
                      // of the linear ramp over the voxel is its value at the centre.
                      const double d = outside(p);
                      if (d > 0.0 && d < 0.025 + 1e-9) return;
                      if (std::abs(d - 0.2) < 0.025 + 1e-9) return;
                      // float(0.1) and float(0.3) differ from 0.1, 0.3 by ~1e-8.
                      worst = std::max(worst, std::abs(f - formula(p)));
                      ++samples;
                  });
    INFO(samples << " centres, worst |f - ramp| " << worst);
    CHECK(samples > 100000);
    CHECK(worst < 1e-7);
    // Straight above the middle: the top value fading over the falloff.
    CHECK(proceduralValue(slab, {0.0, 0.6, 0.0}) == Approx(0.4f * 0.5).epsilon(1e-6));
    CHECK(proceduralValue(slab, {0.0, 0.0, 0.0}) == Approx(0.25f).epsilon(1e-6));
    // On the surface the voxel holds the mean of 1 over its inner half and of the ramp over its
    // outer half: 1 − h / (8 falloff); at the falloff's end, the ramp's last h/2: h / (8 falloff).
    CHECK(proceduralValue(slab, {0.0, 0.5, 0.0}) == Approx(0.4 * (1.0 - 0.05 / 1.6)).epsilon(1e-6));
    CHECK(proceduralValue(slab, {0.0, 0.7, 0.0}) == Approx(0.4 * 0.05 / 1.6).epsilon(1e-6));
}

TEST_CASE("a sharp edge by either filter: 1/2 on the surface, the volume kept", "[procedural]") {
    const double h = 0.1;
    // Box, no falloff: the voxel's coverage, clamp(1/2 − d/h, 0, 1).
    CHECK(edgeWeight(-0.05, 0.0, h, EdgeFilter::Box) == 1.0);
    CHECK(edgeWeight(0.0, 0.0, h, EdgeFilter::Box) == Approx(0.5).epsilon(1e-12));
    CHECK(edgeWeight(0.02, 0.0, h, EdgeFilter::Box) == Approx(0.3).epsilon(1e-12));
    CHECK(edgeWeight(0.05, 0.0, h, EdgeFilter::Box) == 0.0);
    // B-spline, no falloff: 1 − ∫ B up to d/h; ∫ B up to −1 is (1/6) ∫ (2 + x)³ = 1/24.
    CHECK(edgeWeight(0.0, 0.0, h, EdgeFilter::BSpline) == Approx(0.5).epsilon(1e-12));
    CHECK(edgeWeight(0.1, 0.0, h, EdgeFilter::BSpline) == Approx(1.0 / 24.0).epsilon(1e-12));
    CHECK(edgeWeight(-0.1, 0.0, h, EdgeFilter::BSpline) == Approx(23.0 / 24.0).epsilon(1e-12));
    CHECK(edgeWeight(0.2, 0.0, h, EdgeFilter::BSpline) == 0.0);
    CHECK(edgeWeight(-0.2, 0.0, h, EdgeFilter::BSpline) == 1.0);
    for (EdgeFilter filter : {EdgeFilter::Box, EdgeFilter::BSpline}) {
        INFO((filter == EdgeFilter::Box ? "box" : "bspline"));
        // A falloff of many voxels: the ramp itself, away from its ends.
        CHECK(edgeWeight(0.5, 2.0, h, filter) == Approx(0.75).epsilon(1e-12));
        // A falloff far below a voxel is the step.
        CHECK(edgeWeight(0.01, 1e-12, h, filter) ==
              Approx(edgeWeight(0.01, 0.0, h, filter)).epsilon(1e-9));
        // The weight falls monotonically, from 1 to 0, for every falloff.
        for (double falloff : {0.0, 0.03, 0.1, 0.35}) {
            double last = 1.0;
            for (double d = -0.25; d <= falloff + 0.25; d += 0.001) {
                const double w = edgeWeight(d, falloff, h, filter);
                CHECK(w <= last + 1e-12);
                last = w;
            }
            CHECK(last == 0.0);
            // A flat edge at any offset p: the samples at the voxel centres sum to the volume
            // inside it (both filters' integer shifts sum to 1), 10 voxels below plus p/h.
            for (double p : {0.0, 0.013, 0.05, 0.077}) {
                double sum = 0.0;
                for (int k = -10; k < 20; ++k)
                    sum += edgeWeight((k + 0.5) * h - p, falloff, h, filter);
                CHECK(sum == Approx(10.0 + (p + 0.5 * falloff) / h).epsilon(1e-4));
            }
        }
    }

    // A sharp sphere of radius 6.3 voxels: the field's integral is the sphere's volume to 0.1 %
    // (measured, box: −0.011 %, the plane's coverage without the sphere's bend +0.62 %, the step
    // sampled at voxel centres −0.32 %, its error set by where centres happen to fall; B-spline:
    // −0.0002 %), and sampled trilinearly, as the renderer samples it, the field crosses 1/2
    // within 0.15 voxel of the surface along any ray from the centre (measured, box: 0.09-0.11
    // voxel inside, B-spline: 0.07-0.12; a step crosses 1/2 halfway between the last centre in
    // and the first out, up to 0.5 voxel off).
    ensureOpenVdbInitialized();
    const glm::vec3 centre(0.013f, -0.021f, 0.034f);
    const float radius = 0.63f;
    for (EdgeFilter filter : {EdgeFilter::Box, EdgeFilter::BSpline}) {
        SourceSpec ball = test::sphereSource("n", centre, radius, 1.0f, 0.0f, 0.1f);
        ball.edgeFilter = filter;
        const auto grid = makeProceduralField(ball);
        double sum = 0.0;
        for (auto it = grid->cbeginValueOn(); it; ++it) sum += double(*it);
        const double volume = sum * 0.001;
        const double exact = 4.0 / 3.0 * 3.14159265358979 * std::pow(double(radius), 3.0);
        INFO((filter == EdgeFilter::Box ? "box" : "bspline")
             << ": integral " << volume << ", sphere " << exact);
        CHECK(std::abs(volume / exact - 1.0) < 0.001);
        for (const glm::dvec3 dir : {glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(1, 1, 0)),
                                     glm::normalize(glm::dvec3(1, 2, 3)), glm::dvec3(0, 0, -1)}) {
            const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler>
                sample(*grid);
            auto at = [&](double r) {
                const glm::dvec3 p = glm::dvec3(centre) + r * dir;
                return double(sample.wsSample(openvdb::Vec3d(p.x, p.y, p.z)));
            };
            double lo = 0.4, hi = 0.9;
            for (int i = 0; i < 60; ++i) (at(0.5 * (lo + hi)) > 0.5 ? lo : hi) = 0.5 * (lo + hi);
            INFO("direction " << dir.x << " " << dir.y << " " << dir.z << ": 1/2 at r = " << lo);
            CHECK(std::abs(lo - double(radius)) < 0.15 * 0.1);
        }
    }
}

TEST_CASE("rounded box: the box shrunk by the radius, grown by it", "[procedural]") {
    SourceSpec box = test::boxSource("density", glm::vec3(-0.5f), glm::vec3(0.5f), 2.0f);
    box.cornerRadius = 0.2f;
    // The surface is where the field is half the value (a voxel's coverage, 0.05 wide here):
    // the middle of the faces, ...
    const double h = box.voxelSize;
    CHECK(proceduralValue(box, {0.5, 0.0, 0.0}) == Approx(1.0).epsilon(1e-6));
    CHECK(proceduralValue(box, {0.5 - 0.5 * h, 0.0, 0.0}) == Approx(2.0).epsilon(1e-6));
    CHECK(proceduralValue(box, {0.0, -0.5 - 0.5 * h, 0.2}) == 0.0);
    // ... an edge, a quarter cylinder of radius 0.2 about (0.3, 0.3, z), ...
    const double edge = 0.3 + 0.2 / std::sqrt(2.0);
    CHECK(proceduralValue(box, {edge, edge, 0.1}) == Approx(1.0).epsilon(1e-6));
    const double e = 0.5 * h / std::sqrt(2.0);
    CHECK(proceduralValue(box, {edge - e, edge - e, 0.1}) == Approx(2.0).epsilon(1e-6));
    CHECK(proceduralValue(box, {edge + e, edge + e, 0.1}) == 0.0);
    // ... a corner, an eighth of a sphere about (0.3, 0.3, 0.3).
    const double corner = 0.3 + 0.2 / std::sqrt(3.0);
    CHECK(proceduralValue(box, glm::dvec3(corner)) == Approx(1.0).epsilon(1e-6));
    CHECK(proceduralValue(box, glm::dvec3(corner + 0.5 * h / std::sqrt(3.0))) == 0.0);
    // Radius 0 is the plain box, voxel for voxel.
    ensureOpenVdbInitialized();
    box.cornerRadius = 0.0f;
    box.falloff = 0.15f;
    const auto plain = makeBoxField(glm::vec3(-0.5f), glm::vec3(0.5f), 2.0f, 0.15f, 0.05f);
    const auto general = makeProceduralField(box);
    CHECK(plain->activeVoxelCount() == general->activeVoxelCount());
    auto acc = general->getConstAccessor();
    for (auto it = plain->cbeginValueOn(); it; ++it) CHECK(acc.getValue(it.getCoord()) == *it);
}

TEST_CASE("clip boxes split one shape into layers with no gap and no overlap", "[procedural]") {
    ensureOpenVdbInitialized();
    SourceSpec whole = test::boxSource("n", glm::vec3(-0.5f), glm::vec3(0.5f), 1.0f, 0.1f, 0.05f);
    whole.cornerRadius = 0.15f;
    const float cuts[] = {-1.0f, -0.15f, 0.2f, 1.0f};
    openvdb::FloatGrid::Ptr layers[3];
    for (int l = 0; l < 3; ++l) {
        SourceSpec layer = whole;
        layer.clip = Bounds3{glm::vec3(-1.0f, cuts[l], -1.0f), glm::vec3(1.0f, cuts[l + 1], 1.0f)};
        layers[l] = makeProceduralField(layer);
    }
    const auto reference = makeProceduralField(whole);
    int overlaps = 0, mismatches = 0;
    auto a0 = layers[0]->getConstAccessor();
    auto a1 = layers[1]->getConstAccessor();
    auto a2 = layers[2]->getConstAccessor();
    forEachCentre(*reference, glm::vec3(-0.7f), glm::vec3(0.7f), [&](glm::dvec3 p, double f) {
        const openvdb::Coord c =
            reference->transform().worldToIndexCellCentered(openvdb::Vec3d(p.x, p.y, p.z));
        const float v[3] = {a0.getValue(c), a1.getValue(c), a2.getValue(c)};
        int holders = 0;
        for (float x : v) holders += x != 0.0f ? 1 : 0;
        if (holders > 1) ++overlaps;
        if (double(v[0] + v[1] + v[2]) != f) ++mismatches;
    });
    CHECK(overlaps == 0);
    CHECK(mismatches == 0);
    CHECK(layers[1]->activeVoxelCount() > 0);
}

TEST_CASE("procedural keys parse", "[procedural][scene]") {
    const Scene scene = parseScene(R"({
        "sources": [
          {"type": "sphere", "field": "n", "radius": 0.8, "profile": "luneburg", "value": 1},
          {"type": "box", "field": "n.slab", "min": [-2, -1, -1], "max": [2, 0, 1],
           "ramp": {"axis": "z", "from": 0.3, "to": 0}},
          {"type": "box", "field": "n.flint", "corner_radius": 0.25, "falloff": 0.05,
           "clip": {"min": [-1, -0.1, -1], "max": [1, 0.2, 1]}},
          {"type": "sphere", "field": "n", "edge_filter": "box"},
          {"type": "box", "field": "n", "edge_filter": "bspline"}],
        "materials": [{"name": "lens", "field": "n", "ior": 2},
                      {"name": "slab", "field": "n.slab", "ior": 2},
                      {"name": "flint", "field": "n.flint", "ior": 1.6, "absorption": [0, 0.2, 0.4]}]
      })",
                                   "s.json");
    REQUIRE(scene.sources.size() == 5);
    CHECK(scene.sources[0].profile == SourceProfile::Luneburg);
    CHECK(scene.sources[1].profile == SourceProfile::Ramp);
    CHECK(scene.sources[1].rampAxis == 2);
    CHECK(scene.sources[1].rampFrom == 0.3f);
    CHECK(scene.sources[1].rampTo == 0.0f);
    CHECK(scene.sources[1].field == "n.slab");
    CHECK(scene.sources[2].profile == SourceProfile::Uniform);
    CHECK(scene.sources[2].cornerRadius == 0.25f);
    REQUIRE(scene.sources[2].clip.has_value());
    CHECK(scene.sources[2].clip->min == glm::vec3(-1.0f, -0.1f, -1.0f));
    CHECK_FALSE(scene.sources[0].clip.has_value());
    CHECK(scene.materials[2].field == "n.flint");
    // The edge filter: each shape's default unless the source names one.
    CHECK(resolvedEdgeFilter(scene.sources[0]) == EdgeFilter::BSpline);
    CHECK(resolvedEdgeFilter(scene.sources[1]) == EdgeFilter::Box);
    CHECK(resolvedEdgeFilter(scene.sources[3]) == EdgeFilter::Box);
    CHECK(resolvedEdgeFilter(scene.sources[4]) == EdgeFilter::BSpline);
}

TEST_CASE("procedural mistakes name their JSON path", "[procedural][scene]") {
    SECTION("a misspelt ramp key") {
        const Failure f = failureOf(sceneWithSource(
            R"({"type": "box", "field": "n", "ramp": {"axs": "y", "from": 0, "to": 1}})"));
        CHECK(f.where == "lens.json:/sources/0/ramp/axis");
        CHECK_THAT(f.reason, Contains("missing required key 'axis'"));
        CHECK_THAT(f.reason, Contains("'axs'"));
    }
    SECTION("a ramp axis that is not x, y or z") {
        const Failure f = failureOf(sceneWithSource(
            R"({"type": "box", "field": "n", "ramp": {"axis": "w", "from": 0, "to": 1}})"));
        CHECK(f.where == "lens.json:/sources/0/ramp/axis");
        CHECK_THAT(f.reason, Contains(R"(expected one of "x", "y", "z", got "w")"));
    }
    SECTION("a value beside a ramp") {
        const Failure f = failureOf(sceneWithSource(
            R"({"type": "box", "field": "n", "value": 1, "ramp": {"axis": "y", "from": 0, "to": 1}})"));
        CHECK(f.where == "lens.json:/sources/0/value");
        CHECK_THAT(f.reason, Contains("a ramp sets the values"));
    }
    SECTION("an edge filter that does not exist, and one on a luneburg lens") {
        Failure f = failureOf(
            sceneWithSource(R"({"type": "sphere", "field": "n", "edge_filter": "gauss"})"));
        CHECK(f.where == "lens.json:/sources/0/edge_filter");
        CHECK_THAT(f.reason, Contains(R"(expected one of "box", "bspline", got "gauss")"));
        f = failureOf(sceneWithSource(
            R"({"type": "sphere", "field": "n", "profile": "luneburg", "edge_filter": "box"})"));
        CHECK(f.where == "lens.json:/sources/0/edge_filter");
        CHECK_THAT(f.reason, Contains("no step at the surface"));
    }
    SECTION("a falloff on a luneburg lens") {
        const Failure f = failureOf(sceneWithSource(
            R"({"type": "sphere", "field": "n", "profile": "luneburg", "falloff": 0.1})"));
        CHECK(f.where == "lens.json:/sources/0/falloff");
        CHECK_THAT(f.reason, Contains("already 0 at the surface"));
    }
    SECTION("a misspelt profile") {
        const Failure f = failureOf(
            sceneWithSource(R"({"type": "sphere", "field": "n", "profile": "luneberg"})"));
        CHECK(f.where == "lens.json:/sources/0/profile");
        CHECK_THAT(f.reason, Contains(R"(did you mean "luneburg"?)"));
    }
    SECTION("a profile on a box, a corner radius on a sphere") {
        Failure f = failureOf(sceneWithSource(R"({"type": "box", "profile": "luneburg"})"));
        CHECK(f.where == "lens.json:/sources/0/profile");
        CHECK_THAT(f.reason, Contains("unknown key 'profile' for a box source"));
        f = failureOf(sceneWithSource(R"({"type": "sphere", "corner_radus": 0.1})"));
        CHECK(f.where == "lens.json:/sources/0/corner_radus");
        CHECK_THAT(f.reason, Contains("unknown key 'corner_radus' for a sphere source"));
    }
    SECTION("a corner radius beyond half the thinnest side") {
        const Failure f = failureOf(sceneWithSource(
            R"({"type": "box", "min": [0, 0, 0], "max": [2, 0.4, 2], "corner_radius": 0.3})"));
        CHECK(f.where == "lens.json:/sources/0/corner_radius");
        CHECK_THAT(f.reason, Contains("expected a number in [0, 0.2"));
    }
    SECTION("a clip box that misses the shape") {
        const Failure f = failureOf(sceneWithSource(
            R"({"type": "sphere", "radius": 0.5, "clip": {"min": [1, 1, 1], "max": [2, 2, 2]}})"));
        CHECK(f.where == "lens.json:/sources/0/clip");
        CHECK_THAT(f.reason, Contains("expected a clip box that meets the shape"));
    }
}

TEST_CASE("labelled field names: a canonical kind, a dot, a label", "[procedural][scene]") {
    SECTION("a misspelt kind") {
        const Failure f =
            failureOf(sceneWithSource(R"({"type": "sphere", "field": "dnsity.fog"})"));
        CHECK(f.where == "lens.json:/sources/0/field");
        CHECK_THAT(f.reason, Contains(R"(got "dnsity" in "dnsity.fog"; did you mean "density"?)"));
    }
    SECTION("a vector kind") {
        const Failure f = failureOf(sceneWithSource(R"({"type": "sphere", "field": "color.a"})"));
        CHECK(f.where == "lens.json:/sources/0/field");
        CHECK_THAT(f.reason, Contains("expected a scalar field name before '.'"));
    }
    SECTION("an empty or odd label") {
        Failure f = failureOf(sceneWithSource(R"({"type": "sphere", "field": "n."})"));
        CHECK(f.where == "lens.json:/sources/0/field");
        CHECK_THAT(f.reason, Contains("expected a label of letters, digits and '_'"));
        f = failureOf(sceneWithSource(R"({"type": "sphere", "field": "n.a b"})", "n.a b"));
        CHECK(f.where == "lens.json:/sources/0/field");
    }
    SECTION("a material reading a labelled field no source writes") {
        const Failure f =
            failureOf(sceneWithSource(R"({"type": "sphere", "field": "n.crown"})", "n.crwn"));
        CHECK(f.where == "lens.json:/materials/0/field");
        CHECK_THAT(f.reason, Contains("no source writes field 'n.crwn' (sources write: n.crown)"));
        CHECK_THAT(f.reason, Contains(R"(did you mean "n.crown"?)"));
    }
    SECTION("a VDB source may hold it: that is for loading to tell") {
        CHECK_NOTHROW(parseScene(
            R"({"sources": [{"type": "vdb", "file": "a.vdb"}],
                "materials": [{"name": "glass", "field": "n.crown", "ior": 1.5}]})",
            "s.json"));
    }
}

TEST_CASE("negative values of fields that cannot be negative are rejected when parsed",
          "[procedural][scene][bad-input]") {
    SECTION("n") {
        const Failure f =
            failureOf(sceneWithSource(R"({"type": "sphere", "field": "n", "value": -0.5})"));
        CHECK(f.where == "lens.json:/sources/0/value");
        CHECK_THAT(f.reason, Contains("expected a number >= 0 (field 'n' must not be negative: a "
                                      "material maps it to n = 1 + f·(ior − 1), which must not "
                                      "fall below 1), got -0.5"));
    }
    SECTION("a labelled density in a ramp") {
        const Failure f = failureOf(sceneWithSource(
            R"({"type": "box", "field": "density.fog", "ramp": {"axis": "y", "from": 1, "to": -1}})",
            "density.fog"));
        CHECK(f.where == "lens.json:/sources/0/ramp/to");
        CHECK_THAT(f.reason, Contains("field 'density.fog' must not be negative"));
    }
    SECTION("temperature may be negative") {
        CHECK_NOTHROW(
            parseScene(sceneWithSource(R"({"type": "sphere", "field": "temperature", "value": -3})",
                                       "temperature"),
                       "s.json"));
    }
}

TEST_CASE("the index-profile scenes hold what they say", "[procedural][scene]") {
    ensureOpenVdbInitialized();
    const std::string folder = std::string(EIKON_SOURCE_DIR) + "/data/scenes/";
    auto maxValue = [](const openvdb::FloatGrid& grid) {
        float hi = -1e30f;
        for (auto it = grid.cbeginValueOn(); it; ++it) hi = std::max(hi, *it);
        return hi;
    };

    SECTION("luneburg lens: n = sqrt(2 - (r/R)^2), sqrt(2) at the centre") {
        const Scene scene = loadScene(folder + "luneburg_lens.json");
        REQUIRE(scene.sources[0].profile == SourceProfile::Luneburg);
        CHECK(scene.sources[0].value == 1.0f);
        CHECK(scene.materials[0].field == scene.sources[0].field);
        CHECK(scene.materials[0].ior == 2.0f);
        FieldRegistry fields;
        SceneSources(scene).loadFrame(0, fields);
        // The voxel centre nearest the lens's centre is within half a voxel diagonal of it.
        const float peak = maxValue(*fields.floatGrid("n"));
        CHECK(peak <= std::sqrt(2.0f) - 1.0f);
        CHECK(peak > std::sqrt(2.0f) - 1.0f - 0.01f);
    }
    SECTION("mirage slab: n grows with height through the hot layer, then stays") {
        const Scene scene = loadScene(folder + "mirage_slab.json");
        const SourceSpec& layer = scene.sources[0];
        REQUIRE(layer.profile == SourceProfile::Ramp);
        CHECK(layer.rampAxis == 1);
        CHECK(layer.rampFrom < layer.rampTo);
        // The air above carries on at the layer's top value: n is continuous.
        CHECK(scene.sources[1].value == layer.rampTo);
        CHECK(scene.sources[1].boxMin.y == layer.boxMax.y);
        CHECK(scene.environment.type == EnvironmentType::Gradient);
        FieldRegistry fields;
        SceneSources(scene).loadFrame(0, fields);
        auto grid = fields.floatGrid("n");
        auto acc = grid->getConstAccessor();
        float previous = -1.0f;
        bool rising = true;
        for (int j = -20; j < 12; ++j) {  // voxels of 0.025 from y = -0.5 to 0.3
            const float f = acc.getValue(openvdb::Coord(0, j, -100));
            rising = rising && f >= previous;
            previous = f;
        }
        CHECK(rising);
        CHECK(previous == Approx(layer.rampTo));
    }
    SECTION("three glass cube: three labelled glasses, three indices, three colours") {
        const Scene scene = loadScene(folder + "three_glass_cube.json");
        std::vector<std::string> glassFields;
        for (const MaterialSpec& m : scene.materials)
            if (m.ior > 1.0f) glassFields.push_back(m.field);
        REQUIRE(glassFields.size() == 3);
        CHECK(scene.materials[0].ior != scene.materials[1].ior);
        CHECK(scene.materials[1].ior != scene.materials[2].ior);
        CHECK(scene.materials[0].absorption != scene.materials[1].absorption);
        CHECK(scene.materials[1].absorption != scene.materials[2].absorption);
        FieldRegistry fields;
        SceneSources(scene).loadFrame(0, fields);
        // The layers share no voxel and all lie in one rounded cube.
        std::map<openvdb::Coord, int> holders;
        for (const std::string& name : glassFields)
            for (auto it = fields.floatGrid(name)->cbeginValueOn(); it; ++it)
                ++holders[it.getCoord()];
        int shared = 0;
        for (const auto& entry : holders) shared += entry.second > 1 ? 1 : 0;
        CHECK(holders.size() > 30000);  // ~ (1 + 2 · falloff)³ / h³ less the rounding
        CHECK(shared == 0);
        for (const SourceSpec& s : scene.sources)
            if (s.field != "density") CHECK(s.cornerRadius > 0.0f);
    }
    SECTION("houdini smoke behind a glass sphere") {
        const Scene scene = loadScene(folder + "houdini_smoke_glass.json");
        CHECK(scene.sources[0].type == SourceType::Vdb);
        CHECK(scene.sources[1].type == SourceType::Sphere);
        CHECK(scene.sources[1].field == "n");
        CHECK(scene.materials[1].ior == 1.5f);
    }
}

TEST_CASE("the index-profile example in docs/scene-format.md parses", "[procedural][scene]") {
    const std::string path = std::string(EIKON_SOURCE_DIR) + "/docs/scene-format.md";
    std::ifstream in(path);
    const std::string doc{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::size_t section = doc.find("**Index profiles.**");
    REQUIRE(section != std::string::npos);
    const std::string fence = "```json\n";
    const std::size_t begin = doc.find(fence, section);
    REQUIRE(begin != std::string::npos);
    const std::size_t end = doc.find("```", begin + fence.size());
    Scene scene;
    REQUIRE_NOTHROW(
        scene = parseScene(doc.substr(begin + fence.size(), end - begin - fence.size()), path));
    REQUIRE(scene.sources.size() == 3);
    CHECK(scene.sources[0].profile == SourceProfile::Luneburg);
    CHECK(scene.sources[1].profile == SourceProfile::Ramp);
    CHECK(scene.sources[2].clip.has_value());
    CHECK(scene.materials[2].field == "n.flint");
}
