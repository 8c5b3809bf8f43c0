#pragma once
// A jelly: a closed triangle mesh as a mass-spring body that keeps its volume, the physical
// deformer of issue 5. Every vertex is a particle of equal mass; springs along the mesh edges and
// across each pair of adjacent triangles (bending) keep the surface's shape, and a volume
// potential ½·k_v·V₀·(V/V₀ − 1)² keeps the enclosed volume, so the body wobbles instead of
// collapsing. Forces derive from potentials (springs, volume, gravity), integrated by velocity
// Verlet (symplectic): with no damping and no floor the total energy oscillates about its start
// and does not drift. A floor (a plane y = floorY) is a hard constraint: a vertex that crosses it
// is put back on it, loses its velocity into it (an inelastic contact) and is slowed by friction,
// so nothing passes through; pokes add velocity to the vertices near a point. A dropped jelly
// lands, wobbles and comes to rest on the floor.
#include <vector>

#include <glm/vec3.hpp>

#include "core/triangle_mesh.h"

namespace eikon::sim {

struct Poke {
    double time = 0.0;
    glm::vec3 position{0.0f};  // world space
    float radius = 0.1f;       // vertices within this distance get the velocity, falling off
    glm::vec3 velocity{0.0f};  // added at the poke's centre (scene units per second)
};

struct JellySettings {
    float mass = 1.0f;              // the whole body's, spread evenly over the vertices
    float stiffness = 150.0f;       // edge springs: force per unit strain (k = stiffness / rest length)
    float bendStiffness = 40.0f;    // springs across adjacent triangles
    float volumeStiffness = 300.0f; // k_v
    float damping = 0.0f;           // velocity damping per second (0: none)
    glm::vec3 gravity{0.0f, -9.81f, 0.0f};
    bool floor = true;
    float floorY = 0.0f;
    float friction = 5.0f;  // per second, on the tangential velocity in contact
    double fps = 24.0;
    // At least this many steps per frame; more when the springs' highest frequency needs them
    // (velocity Verlet is explicit: substepsPerFrame() says how many it takes).
    int substeps = 40;
    std::vector<Poke> pokes;
};

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
