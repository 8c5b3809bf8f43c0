#include "sim/jelly.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/error.h"

namespace eikon::sim {

Jelly::Jelly(const TriangleMesh& worldMesh, JellySettings settings)
    : settings_(std::move(settings)), rest_(worldMesh) {
    const JellySettings& s = settings_;
    if (rest_.triangles.empty() || rest_.positions.empty())
        throw Error("jelly", "the mesh has no triangles");
    if (!(s.mass > 0.0f && s.stiffness > 0.0f && s.bendStiffness >= 0.0f &&
          s.volumeStiffness >= 0.0f))
        throw Error("jelly", "mass and stiffness must be > 0 (bend and volume stiffness >= 0)");
    if (!(s.damping >= 0.0f && s.friction >= 0.0f))
        throw Error("jelly", "damping and friction must be >= 0");
    if (s.substeps < 1 || !(s.fps > 0.0)) throw Error("jelly", "substeps >= 1 and fps > 0");
    restVolume_ = signedVolume(rest_);
    if (!(restVolume_ > 0.0))
        throw Error("jelly", "the mesh must be closed and wound outward (its volume is " +
                                 std::to_string(restVolume_) + ")");
    particleMass_ = s.mass / float(rest_.positions.size());

    // Edge springs, once per edge; bending springs join the two vertices opposite a shared edge.
    std::map<std::pair<unsigned, unsigned>, unsigned> opposite;  // edge → first opposite vertex
    auto add = [&](unsigned a, unsigned b, float k) {
        const float length = glm::length(rest_.positions[a] - rest_.positions[b]);
        if (length > 0.0f) springs_.push_back({a, b, length, k / length});
    };
    for (const glm::uvec3& t : rest_.triangles)
        for (int e = 0; e < 3; ++e) {
            const unsigned a = t[e], b = t[(e + 1) % 3], o = t[(e + 2) % 3];
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            const auto found = opposite.find(key);
            if (found == opposite.end()) {
                opposite.emplace(key, o);
                add(a, b, s.stiffness);
            } else if (s.bendStiffness > 0.0f) {
                add(found->second, o, s.bendStiffness);
            }
        }
    // Velocity Verlet is stable for ω·dt < 2. By Gershgorin, the springs' highest frequency is at
    // most sqrt(2·max_i Σ_j k_ij / m); take enough substeps for ω·dt ≤ 0.5 (the margin covers the
    // volume term), never fewer than asked.
    std::vector<double> stiffnessAt(rest_.positions.size(), 0.0);
    for (const Spring& sp : springs_) {
        stiffnessAt[sp.a] += sp.k;
        stiffnessAt[sp.b] += sp.k;
    }
    const double maxStiffness = *std::max_element(stiffnessAt.begin(), stiffnessAt.end());
    const double omega = std::sqrt(2.0 * maxStiffness / particleMass_);
    substeps_ = std::max(s.substeps, int(std::ceil(omega / s.fps / 0.5)));
    reset();
}

void Jelly::reset() {
    mesh_ = rest_;
    velocity_.assign(rest_.positions.size(), glm::vec3(0.0f));
    pending_ = settings_.pokes;
    std::stable_sort(pending_.begin(), pending_.end(),
                     [](const Poke& a, const Poke& b) { return a.time < b.time; });
    frame_ = 0;
}

std::vector<glm::vec3> Jelly::forces(const std::vector<glm::vec3>& x) const {
    const JellySettings& s = settings_;
    std::vector<glm::vec3> f(x.size(), particleMass_ * s.gravity);
    for (const Spring& sp : springs_) {  // E = ½ k (|d| − L)²
        const glm::vec3 d = x[sp.b] - x[sp.a];
        const float length = glm::length(d);
        if (length <= 0.0f) continue;
        const glm::vec3 pull = sp.k * (length - sp.rest) / length * d;
        f[sp.a] += pull;
        f[sp.b] -= pull;
    }
    if (s.volumeStiffness > 0.0f) {  // E = ½ k_v V₀ (V/V₀ − 1)²; ∂V/∂x_a = Σ (x_b × x_c)/6
        double volume = 0.0;
        for (const glm::uvec3& t : rest_.triangles)
            volume +=
                glm::dot(glm::dvec3(x[t.x]), glm::cross(glm::dvec3(x[t.y]), glm::dvec3(x[t.z])));
        volume /= 6.0;
        const float scale = float(-double(s.volumeStiffness) * (volume / restVolume_ - 1.0) / 6.0);
        for (const glm::uvec3& t : rest_.triangles) {
            f[t.x] += scale * glm::cross(x[t.y], x[t.z]);
            f[t.y] += scale * glm::cross(x[t.z], x[t.x]);
            f[t.z] += scale * glm::cross(x[t.x], x[t.y]);
        }
    }
    return f;
}

void Jelly::step(double dt) {
    const JellySettings& s = settings_;
    const float h = float(dt);
    std::vector<glm::vec3>& x = mesh_.positions;
    std::vector<glm::vec3> f = forces(x);
    for (size_t i = 0; i < x.size(); ++i) {
        velocity_[i] += 0.5f * h / particleMass_ * f[i];
        x[i] += h * velocity_[i];
        if (s.floorY && x[i].y < *s.floorY) {
            // Contact: the vertex is put back on the floor and loses its velocity into it
            // (inelastic), and friction drags its sliding.
            x[i].y = *s.floorY;
            velocity_[i].y = std::max(velocity_[i].y, 0.0f);
            const float drag = std::exp(-s.friction * h);
            velocity_[i].x *= drag;
            velocity_[i].z *= drag;
        }
    }
    f = forces(x);
    const float keep = std::exp(-s.damping * h);
    for (size_t i = 0; i < x.size(); ++i) {
        velocity_[i] += 0.5f * h / particleMass_ * f[i];
        velocity_[i] *= keep;
        if (s.floorY && x[i].y <= *s.floorY) velocity_[i].y = std::max(velocity_[i].y, 0.0f);
    }
}

void Jelly::advanceToFrame(int frame) {
    if (frame < frame_) reset();
    const double dt = 1.0 / settings_.fps / substeps_;
    while (frame_ < frame) {
        for (int k = 0; k < substeps_; ++k) {
            const double end = double(frame_) / settings_.fps + double(k + 1) * dt;
            while (!pending_.empty() && pending_.front().time < end) {
                const Poke& p = pending_.front();
                for (size_t i = 0; i < velocity_.size(); ++i) {
                    const float d = glm::length(mesh_.positions[i] - p.position);
                    if (d < p.radius) velocity_[i] += (1.0f - d / p.radius) * p.velocity;
                }
                pending_.erase(pending_.begin());
            }
            step(dt);
        }
        ++frame_;
        for (const glm::vec3& p : mesh_.positions)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw Error("jelly", "blew up in frame " + std::to_string(frame_) +
                                         " (a vertex is not finite): lower the stiffness or "
                                         "raise substeps");
    }
}

double Jelly::kineticEnergy() const {
    double e = 0.0;
    for (const glm::vec3& v : velocity_) e += 0.5 * particleMass_ * double(glm::dot(v, v));
    return e;
}

double Jelly::potentialEnergy() const {
    const JellySettings& s = settings_;
    const std::vector<glm::vec3>& x = mesh_.positions;
    double e = 0.0;
    for (const Spring& sp : springs_) {
        const double stretch = double(glm::length(x[sp.b] - x[sp.a])) - double(sp.rest);
        e += 0.5 * double(sp.k) * stretch * stretch;
    }
    const double ratio = volume() / restVolume_ - 1.0;
    e += 0.5 * double(s.volumeStiffness) * restVolume_ * ratio * ratio;
    for (const glm::vec3& p : x) e -= double(particleMass_) * double(glm::dot(s.gravity, p));
    return e;
}

}  // namespace eikon::sim
