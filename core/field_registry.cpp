#include "core/field_registry.h"

#include <algorithm>

#include "core/error.h"
#include "core/printable.h"

namespace eikon {

const std::vector<std::string>& canonicalFieldNames() {
    static const std::vector<std::string> names = {
        field::kDensity, field::kTemperature, field::kVelocity,   field::kFlame,  field::kColor,
        field::kIor,     field::kExtinction,  field::kScattering, field::kPhaseG, field::kEmission};
    return names;
}

bool isCanonicalFieldName(const std::string& name) {
    const auto& names = canonicalFieldNames();
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::string fieldKind(const std::string& name) {
    return name.substr(0, name.find('.'));
}

bool fieldMustBeNonNegative(const std::string& name) {
    const std::string kind = fieldKind(name);
    return kind == field::kDensity || kind == field::kExtinction || kind == field::kScattering ||
           kind == field::kFlame || kind == field::kIor;
}

bool Field::isScalar() const {
    return grid && grid->isType<openvdb::FloatGrid>();
}
bool Field::isVector() const {
    return grid && grid->isType<openvdb::Vec3SGrid>();
}
bool Field::isStaggered() const {
    return isVector() && grid->getGridClass() == openvdb::GRID_STAGGERED;
}

Bounds3 Field::activeWorldBounds() const {
    const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
    if (box.empty()) return {};
    const openvdb::Vec3d lo = box.min().asVec3d() - openvdb::Vec3d(0.5);
    const openvdb::Vec3d hi = box.max().asVec3d() + openvdb::Vec3d(0.5);
    // Any affine transform: take the box around the eight transformed corners.
    Bounds3 out{glm::vec3(std::numeric_limits<float>::max()),
                glm::vec3(std::numeric_limits<float>::lowest())};
    for (int c = 0; c < 8; ++c) {
        const openvdb::Vec3d corner((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(),
                                    (c & 4) ? hi.z() : lo.z());
        const openvdb::Vec3d w = grid->transform().indexToWorld(corner);
        const glm::vec3 p(float(w.x()), float(w.y()), float(w.z()));
        out.min = glm::min(out.min, p);
        out.max = glm::max(out.max, p);
    }
    return out;
}

void FieldRegistry::set(const std::string& name, openvdb::GridBase::Ptr grid, std::string origin) {
    if (!grid) throw Error(origin, "field '" + name + "' has no grid");
    Field& f = fields_[name];
    f.name = name;
    f.grid = std::move(grid);
    f.origin = std::move(origin);
    f.version = nextVersion_++;
}

const Field& FieldRegistry::get(const std::string& name) const {
    auto it = fields_.find(name);
    if (it != fields_.end()) return it->second;
    throw Error("fields", "no field '" + printable(name) + "' " + presentText());
}

std::string FieldRegistry::presentText() const {
    std::string have;
    // Field names may be grid names from a file: escaped, like every quote of a user's bytes.
    std::string solids;  // a level set is a solid's surface, not a field to map to optics
    for (const auto& [n, f] : fields_) {
        have += (have.empty() ? "" : ", ") + printable(n);
        if (f.grid->getGridClass() == openvdb::GRID_LEVEL_SET)
            solids += (solids.empty() ? "" : ", ") + printable(n);
    }
    if (!solids.empty())
        solids = "; level sets (a solid's surface, not a field): " + solids +
                 "; to render one as an object, give its file to \"meshes\" with the object's "
                 "optics";
    return "(fields present: " + (have.empty() ? std::string("none") : have) + ")" + solids;
}

openvdb::FloatGrid::ConstPtr FieldRegistry::floatGrid(const std::string& name) const {
    const Field& f = get(name);
    if (!f.isScalar())
        throw Error(f.origin, "field '" + name + "' is a " + f.grid->valueType() +
                                  " grid; a float grid is needed here");
    return openvdb::gridConstPtrCast<openvdb::FloatGrid>(f.grid);
}

std::vector<std::string> FieldRegistry::names() const {
    std::vector<std::string> out;
    for (const auto& kv : fields_) out.push_back(kv.first);
    return out;
}

}  // namespace eikon
