#pragma once
// A jelly: a closed triangle mesh as a mass-spring body that keeps its volume, the physical
// deformer of issue 5. Every vertex is a particle of equal mass; springs along the mesh edges and
// across each pair of adjacent triangles (bending) keep the surface's shape, and a volume
// potential ½·k_v·V₀·(V/V₀ − 1)² keeps the enclosed volume, so the body wobbles instead of
// collapsing. Forces derive from potentials (springs, volume, gravity), integrated by velocity
// Verlet (symplectic): with no damping and no floor the total energy oscillates about its start
// and does not drift. A floor (the plane y = floorY, when set) is a hard constraint: a vertex that
// crosses it is put back on it, loses its velocity into it (an inelastic contact) and is slowed by
// friction, so nothing passes through; pokes add velocity to the vertices near a point. A dropped
// jelly lands, wobbles and comes to rest on the floor.
#include <vector>

#include <glm/vec3.hpp>

#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace eikon::sim {

// The body as the scene gives it (core/scene.h JellySpec: mass, stiffnesses, damping, gravity,
// floor, friction, fewest substeps, pokes), and the rate of the clock that steps it.
using Poke = JellyPokeSpec;

struct JellySettings : JellySpec {
    double fps = 24.0;
};

inline JellySettings jellySettings(const JellySpec& body, double fps) {
    JellySettings s;
    static_cast<JellySpec&>(s) = body;
    s.fps = fps;
    return s;
}

class Jelly {
public:
    // `worldMesh`: the jelly at rest, in world space, closed and wound outward. Throws
    // eikon::Error for an empty or inward mesh, or settings out of range (mass, stiffness ≤ 0,
    // damping or friction < 0, substeps < 1).
    Jelly(const TriangleMesh& worldMesh, JellySettings settings);

    // Steps whole frames until the state is that of `frame` (from rest at frame 0; going back
    // restarts), so frame f is the same however it is reached.
    void advanceToFrame(int frame);
    int frame() const { return frame_; }
    int substepsPerFrame() const { return substeps_; }

    // One velocity-Verlet step of dt seconds (tests; advanceToFrame uses the frame's substeps).
    void step(double dt);

    const TriangleMesh& mesh() const { return mesh_; }  // current positions, world space
    double kineticEnergy() const;
    double potentialEnergy() const;  // springs + volume + gravity
    double volume() const { return signedVolume(mesh_); }
    double restVolume() const { return restVolume_; }

private:
    struct Spring {
        unsigned a, b;
        float rest, k;
    };
    std::vector<glm::vec3> forces(const std::vector<glm::vec3>& x) const;
    void reset();

    JellySettings settings_;
    TriangleMesh rest_;
    TriangleMesh mesh_;
    std::vector<glm::vec3> velocity_;
    std::vector<Spring> springs_;
    double restVolume_ = 0.0;
    float particleMass_ = 0.0f;
    int substeps_ = 1;
    int frame_ = 0;
    std::vector<Poke> pending_;
};

}  // namespace eikon::sim
