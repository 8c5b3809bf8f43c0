// As-rigid-as-possible handle editing: the energy never increases across iterations, a rigid
// motion of all handles moves the whole mesh rigidly at zero energy, and a bar bent by lifting one
// end converges; the system is factorized once per handle set.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "core/mesh_primitives.h"
#include "sim/arap_deformer.h"
#include "sim/mesh_check.h"

using eikon::ArapDeformer;
using eikon::TriangleMesh;

namespace {

// A bar 5 long and 0.5 in radius: 16 vertices around, 40 segments (674 vertices).
constexpr std::uint32_t kAround = 16, kSegments = 40;

TriangleMesh bar() {
    return eikon::makeCylinder(0.5f, 5.0f, kAround, kSegments);
}

std::vector<glm::vec3> positionsOf(const TriangleMesh& mesh, const std::vector<std::uint32_t>& v) {
    std::vector<glm::vec3> out;
    for (std::uint32_t i : v) out.push_back(mesh.positions[i]);
    return out;
}

std::vector<std::uint32_t> concat(std::vector<std::uint32_t> a,
                                  const std::vector<std::uint32_t>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// Handles: the first two rings (held) and the last two (lifted by `lift` along +y).
struct BentBar {
    TriangleMesh rest = bar();
    std::vector<std::uint32_t> handles =
        concat(eikon::cylinderRings(kAround, kSegments, 0, 1),
               eikon::cylinderRings(kAround, kSegments, kSegments - 1, kSegments));
    std::vector<glm::vec3> targets(float lift) const {
        std::vector<glm::vec3> t = positionsOf(rest, handles);
        for (glm::vec3& p : t)
            if (p.x > 2.5f) p.y += lift;
        return t;
    }
};

}  // namespace

TEST_CASE("arap energy never increases across local/global iterations", "[arap]") {
    BentBar b;
    ArapDeformer arap(b.rest);
    arap.setHandles(b.handles);
    const std::vector<double> energies = arap.solve(b.targets(2.0f), 40);
    REQUIRE(energies.size() == 40);
    CHECK(energies.front() > 1.0);  // the lift is a real deformation
    for (std::size_t k = 1; k < energies.size(); ++k) {
        INFO("iteration " << k << ": " << energies[k - 1] << " -> " << energies[k]);
        CHECK(energies[k] <= energies[k - 1] * (1.0 + 1e-12));
    }
    CHECK(arap.energy() == Approx(energies.back()).epsilon(1e-5));  // float positions kept
}

TEST_CASE("arap moves the mesh rigidly at zero energy when all handles move rigidly", "[arap]") {
    BentBar b;
    const glm::dquat turn = glm::angleAxis(glm::radians(50.0), glm::normalize(glm::dvec3(1, 2, 3)));
    const glm::dvec3 shift(0.3, -1.2, 2.0);
    auto moved = [&](const glm::vec3& p) { return glm::vec3(turn * glm::dvec3(p) + shift); };

    ArapDeformer arap(b.rest);
    arap.setHandles(b.handles);
    std::vector<glm::vec3> targets;
    for (std::uint32_t h : b.handles) targets.push_back(moved(b.rest.positions[h]));
    // ARAP converges linearly from the rest shape: here 1e-10 by iteration 200, then it stays at
    // the floor the float targets leave (about 2e-12).
    const std::vector<double> energies = arap.solve(targets, 300);
    INFO("first energy " << energies.front() << ", last " << energies.back());
    CHECK(energies.front() > 1e-3);  // starts far from the answer: handles moved, rest did not
    CHECK(energies.back() < 1e-9);
    float worst = 0.0f;
    for (std::size_t i = 0; i < b.rest.positions.size(); ++i)
        worst = std::max(worst, glm::length(arap.positions()[i] - moved(b.rest.positions[i])));
    CHECK(worst < 1e-4f);
    CHECK(eikon::signedVolume(arap.deformedMesh()) ==
          Approx(eikon::signedVolume(b.rest)).epsilon(1e-4));
}

TEST_CASE("arap bends a bar with one end lifted and converges", "[arap]") {
    BentBar b;
    ArapDeformer arap(b.rest);
    arap.setHandles(b.handles);
    const float lift = 1.5f;
    // Iterations until the energy changes by less than 1e-6 of itself from one to the next.
    const int limit = 300;
    const std::vector<double> energies = arap.solve(b.targets(lift), limit);
    int converged = -1;
    for (int k = 1; k < limit && converged < 0; ++k)
        if (energies[k - 1] - energies[k] < 1e-6 * energies[k]) converged = k;
    INFO("energy " << energies.front() << " -> " << energies.back() << ", converged at "
                   << converged);
    REQUIRE(converged > 0);
    CHECK(converged < 100);  // 35 when written

    // The held end stays, the lifted end is where it was put, and the middle rises between
    // them: the bar bends rather than shears, with its length and volume nearly kept.
    const TriangleMesh bent = arap.deformedMesh();
    const glm::vec3 middle = bent.positions[kSegments / 2 * kAround];
    CHECK(bent.positions[0] == b.rest.positions[0]);
    CHECK(bent.positions[kSegments * kAround].y ==
          Approx(b.rest.positions[kSegments * kAround].y + lift));
    CHECK(middle.y > b.rest.positions[kSegments / 2 * kAround].y + 0.2f * lift);
    CHECK(middle.y < b.rest.positions[kSegments / 2 * kAround].y + 0.8f * lift);
    CHECK(eikon::signedVolume(bent) == Approx(eikon::signedVolume(b.rest)).epsilon(0.05));
    CHECK(eikon::checkMesh(bent).degenerateTriangles == 0);
}

TEST_CASE("arap factorizes once per handle set and warm-starts frames", "[arap]") {
    BentBar b;
    ArapDeformer arap(b.rest);
    arap.setHandles(b.handles);
    double last = 0.0;
    for (int frame = 1; frame <= 5; ++frame) last = arap.solve(b.targets(0.3f * frame), 3).back();
    CHECK(arap.factorizations() == 1);
    // Holding the last targets, more frames only lower the energy further.
    CHECK(arap.solve(b.targets(1.5f), 3).back() <= last * (1.0 + 1e-12));
    arap.setHandles(eikon::cylinderRings(kAround, kSegments, 0, 0));
    CHECK(arap.factorizations() == 2);
}

TEST_CASE("arap refuses bad handles and meshes", "[arap]") {
    CHECK_THROWS_AS(ArapDeformer(TriangleMesh{}), eikon::Error);
    TriangleMesh nan = bar();
    nan.positions[3].x = std::nanf("");
    CHECK_THROWS_WITH(ArapDeformer(nan), Catch::Contains("vertex 3 is not finite"));

    ArapDeformer arap(bar());
    CHECK_THROWS_WITH(arap.setHandles({}), Catch::Contains("at least one handle"));
    CHECK_THROWS_WITH(arap.setHandles({1, 2, 1}), Catch::Contains("handle 1 is listed twice"));
    CHECK_THROWS_WITH(arap.setHandles({100000}), Catch::Contains("is not a vertex"));
    CHECK_THROWS_WITH(arap.solve({}, 1), Catch::Contains("solve before setHandles"));
    arap.setHandles({0, 1});
    CHECK_THROWS_WITH(arap.solve({glm::vec3(0.0f)}, 1), Catch::Contains("1 targets for 2 handles"));

    // Two separate bars with handles on one: the other could be anywhere.
    TriangleMesh two = bar();
    const TriangleMesh second = bar();
    const unsigned offset = unsigned(two.positions.size());
    for (glm::vec3 p : second.positions) two.positions.push_back(p + glm::vec3(0, 3, 0));
    for (glm::uvec3 t : second.triangles) two.triangles.push_back(t + glm::uvec3(offset));
    ArapDeformer pair(two);
    CHECK_THROWS_WITH(pair.setHandles({0}), Catch::Contains("has no handle"));
}
