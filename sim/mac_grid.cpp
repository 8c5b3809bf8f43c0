#include "sim/mac_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "sim/sim_parallel.h"

namespace eikon::sim {

void Domain::validate() const {
    if (resolution.x < 1 || resolution.y < 1 || resolution.z < 1)
        throw Error("smoke domain", "the resolution must be at least 1 on every axis");
    if (!(voxelSize > 0.0f) || !std::isfinite(voxelSize))
        throw Error("smoke domain",
                    "the voxel size must be positive, got " + std::to_string(voxelSize));
}

Array3::Array3(glm::ivec3 size, glm::vec3 offset, float value)
    : size_(size),
      offset_(offset),
      values_(std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z), value) {}

void Array3::fill(float value) {
    std::fill(values_.begin(), values_.end(), value);
}

namespace {

// Lower lattice index and weight of the upper one along an axis of n samples, clamped so that
// positions beyond the lattice take the edge value.
inline void locate(float q, int n, int& i0, float& t) {
    if (n == 1 || !(q > 0.0f)) {  // also catches NaN: it then reads the edge, the NaN scan reports
        i0 = 0;
        t = 0.0f;
        return;
    }
    const float top = float(n - 1);
    if (q >= top) {
        i0 = n - 2;
        t = 1.0f;
        return;
    }
    i0 = int(q);
    t = q - float(i0);
}

}  // namespace

namespace {

// The eight samples around p and the weights along each axis, as both sample() overloads blend
// them (so that they give the same value bit for bit).
struct Corners {
    float c000, c100, c010, c110, c001, c101, c011, c111;
    float tx, ty, tz;
};

inline Corners cornersAt(const Array3& a, glm::vec3 p) {
    const glm::vec3 q = p - a.offset();
    const glm::ivec3 size = a.size();
    int i, j, k;
    Corners c;
    locate(q.x, size.x, i, c.tx);
    locate(q.y, size.y, j, c.ty);
    locate(q.z, size.z, k, c.tz);
    // With one sample along an axis both "corners" are the same sample.
    const std::size_t sx = size.x > 1 ? 1 : 0;
    const std::size_t sy = size.y > 1 ? std::size_t(size.x) : 0;
    const std::size_t sz = size.z > 1 ? std::size_t(size.x) * std::size_t(size.y) : 0;
    const float* v = a.values().data() + a.index(i, j, k);
    c.c000 = v[0];
    c.c100 = v[sx];
    c.c010 = v[sy];
    c.c110 = v[sx + sy];
    c.c001 = v[sz];
    c.c101 = v[sx + sz];
    c.c011 = v[sy + sz];
    c.c111 = v[sx + sy + sz];
    return c;
}

inline float blend(const Corners& c) {
    const float x00 = c.c000 + c.tx * (c.c100 - c.c000), x10 = c.c010 + c.tx * (c.c110 - c.c010);
    const float x01 = c.c001 + c.tx * (c.c101 - c.c001), x11 = c.c011 + c.tx * (c.c111 - c.c011);
    const float y0 = x00 + c.ty * (x10 - x00), y1 = x01 + c.ty * (x11 - x01);
    return y0 + c.tz * (y1 - y0);
}

}  // namespace

float Array3::sample(glm::vec3 p, float& lo, float& hi) const {
    const Corners c = cornersAt(*this, p);
    lo = std::min({c.c000, c.c100, c.c010, c.c110, c.c001, c.c101, c.c011, c.c111});
    hi = std::max({c.c000, c.c100, c.c010, c.c110, c.c001, c.c101, c.c011, c.c111});
    return blend(c);
}

// Most samples (back-traces, velocities, the unlimited passes) need no range: they skip it.
float Array3::sample(glm::vec3 p) const {
    return blend(cornersAt(*this, p));
}

std::optional<glm::ivec3> Array3::firstNonFinite() const {
    // Each slab records its first bad sample; the lowest slab with one wins, whatever the threads.
    std::vector<int> firstInSlab(std::size_t(size_.z), -1);
    const std::size_t slab = std::size_t(size_.x) * std::size_t(size_.y);
    forEachSlab(size_.z, [&](int k) {
        const float* v = values_.data() + std::size_t(k) * slab;
        for (std::size_t n = 0; n < slab; ++n)
            if (!std::isfinite(v[n])) {
                firstInSlab[std::size_t(k)] = int(n);
                return;
            }
    });
    for (int k = 0; k < size_.z; ++k) {
        const int n = firstInSlab[std::size_t(k)];
        if (n >= 0) return glm::ivec3(n % size_.x, n / size_.x, k);
    }
    return std::nullopt;
}

MacGrid::MacGrid(const Domain& d) : domain(d) {
    domain.validate();
    const glm::ivec3 n = d.resolution;
    for (int a = 0; a < 3; ++a) {
        glm::ivec3 size = n;
        size[a] += 1;
        glm::vec3 offset(0.5f);
        offset[a] = 0.0f;
        velocity[std::size_t(a)] = Array3(size, offset);
    }
    density = Array3(n, glm::vec3(0.5f));
    temperature = Array3(n, glm::vec3(0.5f));
    solid.assign(d.cellCount(), 0);
}

bool MacGrid::inside(int i, int j, int k) const {
    const glm::ivec3 n = domain.resolution;
    return i >= 0 && j >= 0 && k >= 0 && i < n.x && j < n.y && k < n.z;
}

bool MacGrid::faceIsSolid(int axis, int i, int j, int k) const {
    const int along = glm::ivec3(i, j, k)[axis];
    if (along == 0) return domain.wall(axis, false) == Wall::Closed || isSolid(i, j, k);
    if (along == domain.resolution[axis]) {
        glm::ivec3 below(i, j, k);
        below[axis] -= 1;
        return domain.wall(axis, true) == Wall::Closed || isSolid(below.x, below.y, below.z);
    }
    glm::ivec3 below(i, j, k);
    below[axis] -= 1;
    return isSolid(i, j, k) || isSolid(below.x, below.y, below.z);
}

glm::vec3 MacGrid::sampleVelocity(glm::vec3 p) const {
    return {velocity[0].sample(p), velocity[1].sample(p), velocity[2].sample(p)};
}

float MacGrid::maxSpeed(glm::ivec3* where) const {
    glm::vec3 peak(0.0f);
    float fastest = -1.0f;
    for (int a = 0; a < 3; ++a) {
        const Array3& f = velocity[std::size_t(a)];
        // Serial on purpose: a max is exact whatever the order, but the location of ties must
        // not depend on threads, and this is one pass over the faces per frame.
        for (std::size_t n = 0; n < f.count(); ++n) {
            const float s = std::fabs(f[n]);
            if (!(s <= peak[a])) {  // NaN wins too, so a blow-up is located
                peak[a] = std::isfinite(s) ? s : std::numeric_limits<float>::infinity();
                if (where && !(s <= fastest)) {
                    fastest = s;
                    const int nx = f.size().x, ny = f.size().y;
                    glm::ivec3 c(int(n % std::size_t(nx)),
                                 int((n / std::size_t(nx)) % std::size_t(ny)),
                                 int(n / (std::size_t(nx) * std::size_t(ny))));
                    c = glm::min(c, domain.resolution - 1);
                    *where = c;
                }
                if (!std::isfinite(s)) return std::numeric_limits<float>::infinity();
            }
        }
    }
    return std::sqrt(peak.x * peak.x + peak.y * peak.y + peak.z * peak.z);
}

std::string velocityComponentName(int axis) {
    static const char* kAxes[] = {"x", "y", "z"};
    return std::string("velocity (") + kAxes[axis] + " faces)";
}

}  // namespace eikon::sim
