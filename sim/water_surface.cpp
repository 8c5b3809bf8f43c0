#include "sim/water_surface.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "sim/sim_parallel.h"

namespace eikon::sim {

namespace {

constexpr double kCfl = 0.5;  // c·dt/dx; leapfrog in 2D is stable to 1/√2

}  // namespace

WaterSurface::WaterSurface(WaterSettings settings) : settings_(std::move(settings)) {
    const WaterSettings& s = settings_;
    if (s.cells.x < 2 || s.cells.y < 2 || s.cells.x > 4096 || s.cells.y > 4096)
        throw Error("water surface", "cells must be 2 to 4096 along each axis");
    if (!(s.size.x > 0.0f && s.size.y > 0.0f && s.depth > 0.0f && s.waveSpeed > 0.0f))
        throw Error("water surface", "size, depth and wave speed must be > 0");
    if (!(s.damping >= 0.0f)) throw Error("water surface", "damping must be >= 0");
    if (!(s.fps > 0.0)) throw Error("water surface", "fps must be > 0");
    for (size_t d = 0; d < s.droplets.size(); ++d) {
        const Droplet& drop = s.droplets[d];
        if (!(drop.radius > 0.0f) || !(drop.time >= 0.0) ||
            std::abs(drop.position.x) > 0.5f * s.size.x ||
            std::abs(drop.position.y) > 0.5f * s.size.y)
            throw Error("water surface", "droplet " + std::to_string(d) +
                                             " must have a radius > 0, a time >= 0 and lie in "
                                             "the pool");
    }
    dx_ = s.size / glm::vec2(s.cells);
    const double h = std::min(dx_.x, dx_.y);
    substeps_ = std::max(1, int(std::ceil(s.waveSpeed / s.fps / (kCfl * h))));
    reset();
}

void WaterSurface::reset() {
    h_.assign(size_t(settings_.cells.x) * size_t(settings_.cells.y), 0.0f);
    previous_ = h_;
    pending_ = settings_.droplets;
    std::stable_sort(pending_.begin(), pending_.end(),
                     [](const Droplet& a, const Droplet& b) { return a.time < b.time; });
    frame_ = 0;
    time_ = 0.0;
}

void WaterSurface::applyDroplet(const Droplet& d) {
    // A Gaussian dent applied to both time levels (a displacement at rest), its volume given
    // back evenly so that the pool's volume is unchanged.
    const glm::ivec2 n = settings_.cells;
    std::vector<float> dent(h_.size());
    double removed = 0.0;
    for (int k = 0; k < n.y; ++k)
        for (int i = 0; i < n.x; ++i) {
            const glm::vec2 x(-0.5f * settings_.size.x + (float(i) + 0.5f) * dx_.x,
                              -0.5f * settings_.size.y + (float(k) + 0.5f) * dx_.y);
            const glm::vec2 r = x - d.position;
            const float v =
                d.depth * std::exp(-(r.x * r.x + r.y * r.y) / (2.0f * d.radius * d.radius));
            dent[index(i, k)] = v;
            removed += v;
        }
    const float giveBack = float(removed / double(h_.size()));
    for (size_t c = 0; c < h_.size(); ++c) {
        h_[c] += giveBack - dent[c];
        previous_[c] += giveBack - dent[c];
    }
}

void WaterSurface::step(double dt) {
    const glm::ivec2 n = settings_.cells;
    const double cx = double(settings_.waveSpeed) * dt / dx_.x;
    const double cz = double(settings_.waveSpeed) * dt / dx_.y;
    const float ax = float(cx * cx), az = float(cz * cz);
    const float keep = float(1.0 - double(settings_.damping) * dt);
    std::vector<float> next(h_.size());
    // Rows are independent: each writes only its own cells of `next`.
    forEachSlab(n.y, [&](int k) {
        for (int i = 0; i < n.x; ++i) {
            const float c = h_[index(i, k)];
            // Zero flux through the walls: a missing neighbour counts as the cell itself.
            const float west = i > 0 ? h_[index(i - 1, k)] : c;
            const float east = i + 1 < n.x ? h_[index(i + 1, k)] : c;
            const float south = k > 0 ? h_[index(i, k - 1)] : c;
            const float north = k + 1 < n.y ? h_[index(i, k + 1)] : c;
            const float laplacian =
                ax * ((east - c) - (c - west)) + az * ((north - c) - (c - south));
            next[index(i, k)] = c + keep * (c - previous_[index(i, k)]) + laplacian;
        }
    });
    previous_ = std::move(h_);
    h_ = std::move(next);
    time_ += dt;
}

void WaterSurface::advanceToFrame(int frame) {
    if (frame < frame_) reset();
    const double dt = 1.0 / settings_.fps / substeps_;
    while (frame_ < frame) {
        for (int s = 0; s < substeps_; ++s) {
            // Droplets fall at the start of the substep whose interval holds their time.
            const double end = double(frame_) / settings_.fps + double(s + 1) * dt;
            while (!pending_.empty() && pending_.front().time < end) {
                applyDroplet(pending_.front());
                pending_.erase(pending_.begin());
            }
            step(dt);
        }
        ++frame_;
        time_ = double(frame_) / settings_.fps;  // no drift from summing dt
    }
}

double WaterSurface::volumeAboveRest() const {
    double sum = 0.0;
    for (float h : h_) sum += double(h);
    return sum * double(dx_.x) * double(dx_.y);
}

TriangleMesh WaterSurface::mesh() const {
    const glm::ivec2 n = settings_.cells;
    const int cx = n.x + 1, cz = n.y + 1;  // corners
    TriangleMesh m;
    m.positions.reserve(size_t(2 * cx * cz));
    for (int layer = 0; layer < 2; ++layer)  // 0: surface, 1: bottom
        for (int k = 0; k < cz; ++k)
            for (int i = 0; i < cx; ++i) {
                float y = 0.0f;
                if (layer == 0) {  // the mean of the (up to four) cells around the corner
                    float sum = 0.0f;
                    int count = 0;
                    for (int dk = -1; dk <= 0; ++dk)
                        for (int di = -1; di <= 0; ++di) {
                            const int ci = i + di, ck = k + dk;
                            if (ci < 0 || ck < 0 || ci >= n.x || ck >= n.y) continue;
                            sum += h_[index(ci, ck)];
                            ++count;
                        }
                    y = settings_.depth + sum / float(count);
                }
                m.positions.push_back({-0.5f * settings_.size.x + float(i) * dx_.x, y,
                                       -0.5f * settings_.size.y + float(k) * dx_.y});
            }
    auto corner = [&](int layer, int i, int k) { return unsigned(layer * cx * cz + k * cx + i); };
    // Outward: the surface faces +y, the bottom −y. (x × z = −y, hence the orders.)
    for (int k = 0; k < n.y; ++k)
        for (int i = 0; i < n.x; ++i) {
            const unsigned a = corner(0, i, k), b = corner(0, i + 1, k),
                           c = corner(0, i + 1, k + 1), d = corner(0, i, k + 1);
            m.triangles.push_back({a, c, b});
            m.triangles.push_back({a, d, c});
            const unsigned e = corner(1, i, k), f = corner(1, i + 1, k),
                           g = corner(1, i + 1, k + 1), h = corner(1, i, k + 1);
            m.triangles.push_back({e, f, g});
            m.triangles.push_back({e, g, h});
        }
    // Walls: each boundary edge of the surface joined to the same edge of the bottom.
    auto wall = [&](int i0, int k0, int i1, int k1) {  // surface edge (i0,k0)→(i1,k1), then down
        const unsigned a = corner(0, i0, k0), b = corner(0, i1, k1);
        const unsigned c = corner(1, i1, k1), d = corner(1, i0, k0);
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
    };
    for (int i = 0; i < n.x; ++i) {
        wall(i, 0, i + 1, 0);      // z = min, facing −z
        wall(i + 1, n.y, i, n.y);  // z = max, facing +z
    }
    for (int k = 0; k < n.y; ++k) {
        wall(0, k + 1, 0, k);      // x = min, facing −x
        wall(n.x, k, n.x, k + 1);  // x = max, facing +x
    }
    return m;
}

}  // namespace eikon::sim
