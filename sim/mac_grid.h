#pragma once
// The smoke solver's state on a MAC (staggered) grid over a box: velocity components on the faces
// of the cells, density and temperature at their centres, and which cells are solid.
//
// Positions are in cell index space: cell (i, j, k) spans [i, i+1) × [j, j+1) × [k, k+1), so its
// centre is at (i+½, j+½, k+½) and the x face between cells i-1 and i lies at x = i. World space
// is origin + p·voxelSize.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace eikon::sim {

// What lies beyond a face of the domain: a closed wall is a solid (no flow through it), an open
// one is free air at zero pressure (smoke leaves through it).
enum class Wall { Closed, Open };

struct Domain {
    glm::ivec3 resolution{32};
    float voxelSize = 0.1f;  // scene units per cell
    glm::vec3 origin{0.0f};  // world position of the corner of cell (0, 0, 0)
    // Walls in the order -x, +x, -y, +y, -z, +z.
    std::array<Wall, 6> walls{Wall::Closed, Wall::Closed, Wall::Closed,
                              Wall::Closed, Wall::Closed, Wall::Closed};

    Wall wall(int axis, bool upper) const { return walls[std::size_t(2 * axis + (upper ? 1 : 0))]; }
    std::size_t cellCount() const {
        return std::size_t(resolution.x) * std::size_t(resolution.y) * std::size_t(resolution.z);
    }
    glm::vec3 worldFromIndex(glm::vec3 p) const { return origin + p * voxelSize; }
    glm::vec3 indexFromWorld(glm::vec3 w) const { return (w - origin) / voxelSize; }
    glm::vec3 cellCenter(int i, int j, int k) const {
        return worldFromIndex(glm::vec3(i, j, k) + 0.5f);
    }
    // Throws eikon::Error when the resolution or voxel size is unusable.
    void validate() const;
};

// A dense lattice of float samples; sample (0, 0, 0) sits at `offset` in cell index space (½ on
// every axis for centres, 0 on its own axis for a face component). x varies fastest.
class Array3 {
public:
    Array3() = default;
    Array3(glm::ivec3 size, glm::vec3 offset, float value = 0.0f);

    glm::ivec3 size() const { return size_; }
    glm::vec3 offset() const { return offset_; }
    std::size_t count() const { return values_.size(); }
    std::size_t index(int i, int j, int k) const {
        return (std::size_t(k) * std::size_t(size_.y) + std::size_t(j)) * std::size_t(size_.x) +
               std::size_t(i);
    }
    float& operator()(int i, int j, int k) { return values_[index(i, j, k)]; }
    float operator()(int i, int j, int k) const { return values_[index(i, j, k)]; }
    float& operator[](std::size_t n) { return values_[n]; }
    float operator[](std::size_t n) const { return values_[n]; }
    std::vector<float>& values() { return values_; }
    const std::vector<float>& values() const { return values_; }
    glm::vec3 position(int i, int j, int k) const { return glm::vec3(i, j, k) + offset_; }
    void fill(float value);

    // Trilinear interpolation at p (cell index space). Outside the lattice the nearest edge value
    // is used (zero-gradient extrapolation). lo/hi, when given, receive the smallest and largest
    // of the samples that were blended: the range a limiter clamps to.
    float sample(glm::vec3 p) const;
    float sample(glm::vec3 p, float& lo, float& hi) const;

    // The first (lowest-index) sample that is NaN or infinite, if any.
    std::optional<glm::ivec3> firstNonFinite() const;

private:
    glm::ivec3 size_{0};
    glm::vec3 offset_{0.0f};
    std::vector<float> values_;
};

struct MacGrid {
    explicit MacGrid(const Domain& domain);

    Domain domain;
    // velocity[a] holds the a-component on the faces normal to axis a: resolution + 1 along a.
    std::array<Array3, 3> velocity;
    Array3 density;
    Array3 temperature;
    std::vector<std::uint8_t> solid;  // per cell, 1 inside an obstacle

    glm::ivec3 resolution() const { return domain.resolution; }
    std::size_t cellIndex(int i, int j, int k) const { return density.index(i, j, k); }
    bool isSolid(int i, int j, int k) const { return solid[cellIndex(i, j, k)] != 0; }
    bool inside(int i, int j, int k) const;
    // The face of `axis` at lattice index (i, j, k) (between cell (i,j,k) - e_axis and (i,j,k))
    // is solid when either side is a solid cell or a closed wall: its velocity is the solid's (0).
    bool faceIsSolid(int axis, int i, int j, int k) const;

    // Velocity in scene units per second at p (cell index space), each component interpolated
    // from its own faces.
    glm::vec3 sampleVelocity(glm::vec3 p) const;
    // The largest speed anywhere in the grid can reach: |(max|u|, max|v|, max|w|)|, an upper bound
    // on every trilinear blend of the faces. `where` receives the cell next to the fastest face.
    float maxSpeed(glm::ivec3* where = nullptr) const;
};

// Names a velocity component for messages: "velocity (x faces)".
std::string velocityComponentName(int axis);

}  // namespace eikon::sim
