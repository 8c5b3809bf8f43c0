#pragma once
// Named fields held as OpenVDB grids with their transforms. Simulations write them, VDB import
// fills them, materials read them. Each replacement bumps the field's version so that the GPU
// upload can skip fields that did not change.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/bounds.h"

namespace eikon {

// Canonical names (docs/architecture.md, "VDB names"): what materials and the pipeline ask for.
namespace field {
inline constexpr const char* kDensity = "density";
inline constexpr const char* kTemperature = "temperature";
inline constexpr const char* kVelocity = "velocity";
inline constexpr const char* kFlame = "flame";
inline constexpr const char* kColor = "color";
inline constexpr const char* kIor = "n";
inline constexpr const char* kExtinction = "kappa";
inline constexpr const char* kScattering = "sigma";
inline constexpr const char* kPhaseG = "g";
inline constexpr const char* kEmission = "emission";
}  // namespace field

const std::vector<std::string>& canonicalFieldNames();
bool isCanonicalFieldName(const std::string& name);
// What kind of field a name is: the part before a '.' label ("n" for "n.crown"), or the name.
std::string fieldKind(const std::string& name);
// Fields whose values are amounts of stuff or optical coefficients (density, flame, kappa, sigma)
// or an index excess that materials map to n = 1 + f·(ior − 1) (n), labelled or not: a negative
// value is meaningless there, and import and the scene parser reject it.
bool fieldMustBeNonNegative(const std::string& name);

struct Field {
    std::string name;  // canonical name, or the grid's own name when no alias matched
    openvdb::GridBase::Ptr grid;
    std::string origin;  // where it came from, for messages: "smoke.vdb:density", "/sources/0"
    std::uint64_t version = 0;

    bool isScalar() const;     // float grid
    bool isVector() const;     // vec3s grid
    bool isStaggered() const;  // vec3 grid of class staggered (face-centred, MAC)
    // World-space box covered by the active voxels (cell i spans [i-0.5, i+0.5] in index space).
    Bounds3 activeWorldBounds() const;
};

class FieldRegistry {
public:
    // Stores `grid` under `name`, replacing any previous field of that name.
    void set(const std::string& name, openvdb::GridBase::Ptr grid, std::string origin);
    bool has(const std::string& name) const { return fields_.count(name) != 0; }
    // Throws eikon::Error naming the missing field and the fields there are.
    const Field& get(const std::string& name) const;
    openvdb::FloatGrid::ConstPtr floatGrid(const std::string& name) const;
    std::vector<std::string> names() const;
    // For a message about a field that is missing: "(fields present: a, b)", and where some are
    // level sets (solids' surfaces, which optics do not read as fields), where they belong.
    std::string presentText() const;
    void clear() { fields_.clear(); }

private:
    std::map<std::string, Field> fields_;
    std::uint64_t nextVersion_ = 1;
};

}  // namespace eikon
