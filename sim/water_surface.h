#pragma once
// A water surface as a height field under the damped wave equation, h_tt = c²∇²h − γ h_t, the
// classic source of moving caustics: a pool of water whose surface ripples from droplets. Heights
// live at cell centres of an nx × nz grid with closed (reflecting) walls; stepped by leapfrog
// (explicit, second order), stable for c·dt/dx ≤ 1/√2, so a frame takes as many equal substeps as
// the CFL number 0.5 asks. The 5-point Laplacian in flux form with zero-flux walls sums to zero,
// so the water's volume Σh·dx·dz is kept to rounding; a droplet is a dent with its volume given
// back evenly over the pool, so it keeps the volume too.
//
// The body of water comes out as a closed triangle mesh (core/triangle_mesh.h) in object space:
// the pool spans x ∈ [−size.x/2, size.x/2], z ∈ [−size.y/2, size.y/2], bottom at y = 0, rest
// surface at y = depth.
#include <vector>

#include <glm/vec2.hpp>

#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace eikon::sim {

// The pool as the scene gives it (core/scene.h WaterSpec: size, cells, depth, wave speed,
// damping, droplets), and the rate of the clock that steps it.
using Droplet = WaterDropletSpec;

struct WaterSettings : WaterSpec {
    double fps = 24.0;
};

inline WaterSettings waterSettings(const WaterSpec& pool, double fps) {
    WaterSettings s;
    static_cast<WaterSpec&>(s) = pool;
    s.fps = fps;
    return s;
}

class WaterSurface {
public:
    // Throws eikon::Error for cells < 2, sizes, depth or speed ≤ 0, damping < 0, a droplet
    // outside the pool or with a radius ≤ 0.
    explicit WaterSurface(WaterSettings settings);

    // Steps whole frames until the state is that of `frame` (from frame 0 at rest; going back
    // restarts from rest), so frame f is the same however it is reached.
    void advanceToFrame(int frame);
    int frame() const { return frame_; }
    int substepsPerFrame() const { return substeps_; }
    double time() const { return time_; }

    // Height above the rest surface at cell (i, k), and Σ h·dx·dz over the pool (the water's
    // volume above y = depth; its change is what conservation bounds).
    float height(int i, int k) const { return h_[index(i, k)]; }
    double volumeAboveRest() const;
    float cellSize() const { return dx_.x; }

    // The body of water as a closed mesh: the surface through the cell corners (each corner the
    // mean of its cells), a flat bottom of the same grid, and the four walls.
    TriangleMesh mesh() const;

    // One substep of dt seconds (for tests; advanceToFrame uses the frame's substeps).
    void step(double dt);

private:
    size_t index(int i, int k) const { return size_t(k) * size_t(settings_.cells.x) + size_t(i); }
    void reset();
    void applyDroplet(const Droplet& d);

    WaterSettings settings_;
    glm::vec2 dx_;
    int substeps_ = 1;
    int frame_ = 0;
    double time_ = 0.0;
    // Heights above the rest surface (not above the bottom: small numbers keep more bits, so the
    // volume drifts less by rounding).
    std::vector<float> h_, previous_;
    std::vector<Droplet> pending_;  // droplets not yet applied, by time
};

}  // namespace eikon::sim
