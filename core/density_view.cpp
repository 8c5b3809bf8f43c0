#include "core/density_view.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/nanovdb_reader.h"
#include "core/vdb_import.h"
#include "core/vdb_reader.h"
#include "core/world_box.h"

namespace eikon {
namespace {

// As a Bounds3 (floats), the box core/world_box.h gives.
Bounds3 worldBox(const openvdb::math::Transform& xform, const openvdb::CoordBBox& box) {
    const openvdb::BBoxd b = worldBoxOf(xform, box);
    return {glm::vec3(float(b.min().x()), float(b.min().y()), float(b.min().z())),
            glm::vec3(float(b.max().x()), float(b.max().y()), float(b.max().z()))};
}

// Up from the file: metadata a writer left ("up_axis", "upAxis", "up"), else what its writer is
// known to use. Houdini and OpenVDB's tools are y-up; Blender is z-up and its Mantaflow caches
// carry no creator, but their grid names (flags, phi_*) are Mantaflow's own.
void upFromWriter(const VdbReader& reader, DensityView& view) {
    for (const char* key : {"up_axis", "upAxis", "up"}) {
        const openvdb::Metadata::ConstPtr m = reader.fileMetadata()[key];
        if (!m) continue;
        if (const auto axis = parseUpAxis(m->str())) {
            view.up = axis;
            view.upReason = std::string("the file's metadata ") + key + " = " + m->str();
            return;
        }
    }
    const std::string creator = reader.creator();
    if (creator.find("Blender") != std::string::npos) {
        view.up = glm::vec3(0, 0, 1);
        view.upReason = "written by Blender, which is z-up";
        return;
    }
    if (creator.find("Houdini") != std::string::npos) {
        view.up = glm::vec3(0, 1, 0);
        view.upReason = "written by Houdini, which is y-up";
        return;
    }
    bool flags = false, phi = false;
    for (const VdbReader::Entry& e : reader.entries()) {
        flags = flags || e.name == "flags";
        phi = phi || e.name.rfind("phi_", 0) == 0;
    }
    if (flags && phi) {
        view.up = glm::vec3(0, 0, 1);
        view.upReason = "a Blender Mantaflow cache (grids flags, phi_*), which is z-up";
    }
}

}  // namespace

std::optional<glm::vec3> parseUpAxis(const std::string& text) {
    std::string t;
    for (char c : text) t += char(std::tolower(static_cast<unsigned char>(c)));
    if (!t.empty() && t[0] == '+') t.erase(0, 1);
    if (t == "x") return glm::vec3(1, 0, 0);
    if (t == "y") return glm::vec3(0, 1, 0);
    if (t == "z") return glm::vec3(0, 0, 1);
    return std::nullopt;
}

namespace {

// The voxel size, visible box and centroid of a float density grid.
void viewGrid(const openvdb::FloatGrid& grid, DensityView& view) {
    const openvdb::Vec3d vs = grid.voxelSize();
    view.voxelSize = float(std::min({vs.x(), vs.y(), vs.z()}));
    float largest = 0.0f;
    for (auto it = grid.cbeginValueOn(); it; ++it) largest = std::max(largest, *it);
    if (!(largest > 0.0f)) return;
    const float cut = kVisibleFraction * largest;
    openvdb::CoordBBox box;
    openvdb::Vec3d weighted(0.0);
    double mass = 0.0;
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        if (!(*it >= cut)) continue;
        const openvdb::CoordBBox cells = it.getBoundingBox();
        box.expand(cells);
        const double m = double(*it) * double(cells.volume());
        weighted += m * grid.indexToWorld(cells.getCenter());
        mass += m;
    }
    view.visible = worldBox(grid.transform(), box);
    const openvdb::Vec3d c = weighted / mass;
    view.centroid = glm::vec3(float(c.x()), float(c.y()), float(c.z()));
}

openvdb::FloatGrid::Ptr asDensity(const openvdb::GridBase::Ptr& base, const std::string& path,
                                  const std::string& name) {
    const auto grid = openvdb::GridBase::grid<openvdb::FloatGrid>(base);
    if (!grid)
        throw Error(path,
                    "density grid '" + name + "' is " + base->valueType() + ", expected float");
    return grid;
}

[[noreturn]] void noDensity(const std::string& path) {
    throw Error(path, "no density grid (looked for the names density, smoke, soot, density.*)");
}

}  // namespace

DensityView viewDensity(const std::string& path) {
    ensureOpenVdbInitialized();
    DensityView view;
    if (isNanoVdbFile(path)) {  // no file metadata, no writer's name: up is not implied
        for (const NanoVdbGrid& g : readNanoVdb(path))
            if (g.grid && canonicalFieldFor(g.name) == "density") {
                viewGrid(*asDensity(g.grid, path, g.name), view);
                return view;
            }
        noDensity(path);
    }
    VdbReader reader(path);
    upFromWriter(reader, view);
    for (size_t i = 0; i < reader.entries().size(); ++i) {
        const std::string& name = reader.entries()[i].name;
        if (canonicalFieldFor(name) != "density") continue;
        viewGrid(*asDensity(reader.readGrid(i), path, name), view);
        return view;
    }
    noDensity(path);
}

bool holdsDensityGrid(const std::string& path) {
    ensureOpenVdbInitialized();
    if (isNanoVdbFile(path)) {
        for (const NanoVdbGrid& g : readNanoVdb(path))
            if (canonicalFieldFor(g.name) == "density") return true;
        return false;
    }
    const VdbReader reader(path);
    for (const VdbReader::Entry& e : reader.entries())
        if (canonicalFieldFor(e.name) == "density") return true;
    return false;
}

DensityView writerUpOf(const std::string& path) {
    ensureOpenVdbInitialized();
    DensityView view;
    if (!isNanoVdbFile(path)) upFromWriter(VdbReader(path), view);
    return view;
}

}  // namespace eikon
