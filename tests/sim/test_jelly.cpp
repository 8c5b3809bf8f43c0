// The jelly (sim/jelly.h): energy does not drift without damping or floor, a dropped jelly comes
// to rest on the floor without passing through it and keeps its volume, and frame f is the same
// however it is reached.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/mesh_primitives.h"
#include "sim/jelly.h"

using namespace eikon;
using sim::Jelly;
using sim::JellySettings;
using sim::Poke;

TEST_CASE("without damping or floor a poked jelly's energy oscillates and does not drift",
          "[jelly]") {
    JellySettings s;                            // no floor
    s.gravity = glm::vec3(0.0f, -9.81f, 0.0f);  // conservative too: free fall keeps the total
    s.pokes = {Poke{0.0, glm::vec3(0.3f, 1.0f, 0.0f), 0.25f, glm::vec3(-1.5f, 0.5f, 0.0f)}};
    Jelly jelly(icosphere(glm::vec3(0.0f, 1.0f, 0.0f), 0.3f, 2), s);
    jelly.advanceToFrame(1);  // the poke, then 40 steps
    const double e0 = jelly.kineticEnergy() + jelly.potentialEnergy();
    const double wobble = jelly.kineticEnergy();  // the energy scale of the motion
    double worst = 0.0;
    for (int frame = 2; frame <= 26; ++frame) {  // 1,000 more steps
        jelly.advanceToFrame(frame);
        const double e = jelly.kineticEnergy() + jelly.potentialEnergy();
        worst = std::max(worst, std::abs(e - e0));
    }
    INFO("max |E - E0| " << worst << " of kinetic " << wobble);
    CHECK(worst < 1e-2 * wobble);
}

TEST_CASE("a dropped jelly comes to rest on the floor, keeping its volume", "[jelly]") {
    JellySettings s;
    s.damping = 2.0f;
    s.floorY = 0.0f;
    Jelly jelly(icosphere(glm::vec3(0.0f, 1.0f, 0.0f), 0.3f, 2), s);
    float lowest = 1.0f;
    for (int frame = 1; frame <= 144; ++frame) {  // 6 s
        jelly.advanceToFrame(frame);
        for (const glm::vec3& p : jelly.mesh().positions) lowest = std::min(lowest, p.y);
    }
    glm::vec3 centre(0.0f);
    for (const glm::vec3& p : jelly.mesh().positions) centre += p;
    centre /= float(jelly.mesh().positions.size());
    INFO("lowest vertex " << lowest << ", centre " << centre.y << ", kinetic "
                          << jelly.kineticEnergy() << ", volume " << jelly.volume() << " of "
                          << jelly.restVolume());
    CHECK(lowest >= 0.0f);    // never below the floor
    CHECK(centre.y > 0.2f);   // resting on the floor, not through it
    CHECK(centre.y < 0.32f);  // and down, not floating
    // At rest: kinetic energy far below the m·g·h = 1 · 9.81 · 0.7 ≈ 6.9 J the fall released.
    CHECK(jelly.kineticEnergy() < 1e-3);
    CHECK(std::abs(jelly.volume() / jelly.restVolume() - 1.0) < 0.05);
}

TEST_CASE("a jelly's frame is the same however it is reached", "[jelly]") {
    JellySettings s;
    s.floorY = 0.0f;  // it lands within the 20 frames: contact is part of what must repeat
    s.pokes = {Poke{0.1, glm::vec3(0.0f, 1.3f, 0.0f), 0.2f, glm::vec3(0.0f, -2.0f, 0.0f)}};
    Jelly direct(icosphere(glm::vec3(0.0f, 1.0f, 0.0f), 0.3f, 1), s);
    Jelly stepped(icosphere(glm::vec3(0.0f, 1.0f, 0.0f), 0.3f, 1), s);
    direct.advanceToFrame(20);
    for (int f : {5, 13, 20}) stepped.advanceToFrame(f);
    CHECK(direct.mesh().positions == stepped.mesh().positions);
    stepped.advanceToFrame(2);
    stepped.advanceToFrame(20);
    CHECK(direct.mesh().positions == stepped.mesh().positions);
}

TEST_CASE("bad jelly settings and meshes are errors", "[jelly]") {
    JellySettings s;
    s.mass = 0.0f;
    CHECK_THROWS_AS(Jelly(icosphere(glm::vec3(0.0f), 1.0f, 1), s), Error);
    TriangleMesh inward = icosphere(glm::vec3(0.0f), 1.0f, 1);
    for (glm::uvec3& t : inward.triangles) std::swap(t.y, t.z);
    CHECK_THROWS_WITH(Jelly(inward, JellySettings{}), Catch::Contains("wound outward"));
}
