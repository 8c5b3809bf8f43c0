// The "meshes" array of a scene, read as strictly as the rest (see scene.cpp): every error names
// "<file>:/meshes/<i>/...". Keep in step with docs/scene-format.md#meshes.
#include "core/scene_meshes.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/scene_dispersion.h"
#include "core/scene_helpers.h"

namespace eikon {
namespace {

using json::Object;
using json::Range;
using json::Value;

constexpr int kMaxSubdivisions = 7;  // 327,680 triangles
constexpr int kMaxBlurRadius = 16;

bool isNameCharacter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
}

WaterDropletSpec readDroplet(const Value& value, const WaterSpec& water) {
    Object object(value, "a droplet");
    WaterDropletSpec d;
    d.time = object.required("time", "seconds >= 0").number(Range::atLeast(0.0));
    const Value position = object.required("position", "[x, z] inside the pool");
    const std::vector<Value> xz = position.elements("an array of 2 numbers [x, z]", 2);
    if (xz.size() != 2) position.failExpected("an array of 2 numbers [x, z]");
    d.position = {xz[0].floatNumber(Range::closed(-0.5 * water.size.x, 0.5 * water.size.x)),
                  xz[1].floatNumber(Range::closed(-0.5 * water.size.y, 0.5 * water.size.y))};
    if (auto r = object.optional("radius")) d.radius = r->floatNumber(Range::greaterThan(0.0));
    if (auto a = object.optional("depth")) d.depth = a->floatNumber();
    object.finish();
    return d;
}

void readWater(Object& object, WaterSpec& water) {
    const Value size = object.required("size", "an array of 2 numbers > 0 [x, z]");
    const std::vector<Value> sxz = size.elements("an array of 2 numbers > 0 [x, z]", 2);
    if (sxz.size() != 2) size.failExpected("an array of 2 numbers > 0 [x, z]");
    water.size = {sxz[0].floatNumber(Range::greaterThan(0.0)),
                  sxz[1].floatNumber(Range::greaterThan(0.0))};
    if (auto cells = object.optional("cells")) {
        const std::vector<Value> n = cells->elements("an array of 2 integers [nx, nz]", 2);
        if (n.size() != 2) cells->failExpected("an array of 2 integers [nx, nz]");
        water.cells = {int(n[0].integer(2, 4096)), int(n[1].integer(2, 4096))};
    }
    water.depth = object.required("depth", "a number > 0").floatNumber(Range::greaterThan(0.0));
    if (auto c = object.optional("wave_speed"))
        water.waveSpeed = c->floatNumber(Range::greaterThan(0.0));
    if (auto g = object.optional("damping")) water.damping = g->floatNumber(Range::atLeast(0.0));
    if (auto drops = object.optional("droplets"))
        for (const Value& d : drops->elements("an array of droplets"))
            water.droplets.push_back(readDroplet(d, water));
}

// A liquid's container is named here and resolved in readMeshes, which knows the earlier meshes.
void readShape(const Value& value, MeshObjectSpec& mesh, std::string& containerName) {
    Object object(value, "a mesh shape");
    const std::string type =
        object.required("type", "\"icosphere\", \"box\", \"water\" or \"liquid\"")
            .choice({"icosphere", "box", "water", "liquid"});
    if (type == "liquid") {
        object.setKind("a liquid shape");
        mesh.shape = MeshShapeType::Liquid;
        containerName =
            object.required("container", "the name of an earlier mesh (the glass it fills)")
                .nonEmptyString();
        mesh.fill = object.required("fill", "a fraction of the cavity's depth in (0, 1]")
                        .number(Range::openClosed(0.0, 1.0));
    } else if (type == "water") {
        object.setKind("a water shape");
        mesh.shape = MeshShapeType::Water;
        readWater(object, mesh.water);
    } else if (type == "icosphere") {
        object.setKind("an icosphere shape");
        mesh.shape = MeshShapeType::Icosphere;
        mesh.radius =
            object.required("radius", "a number > 0").floatNumber(Range::greaterThan(0.0));
        if (auto s = object.optional("subdivisions"))
            mesh.subdivisions = int(s->integer(0, kMaxSubdivisions));
    } else {
        object.setKind("a box shape");
        mesh.shape = MeshShapeType::Box;
        mesh.boxMin = object.required("min", "an array of 3 numbers [x, y, z]").vec3();
        const Value max = object.required("max", "an array of 3 numbers [x, y, z]");
        mesh.boxMax = max.vec3();
        if (!(mesh.boxMin.x < mesh.boxMax.x && mesh.boxMin.y < mesh.boxMax.y &&
              mesh.boxMin.z < mesh.boxMax.z))
            max.fail("expected max > min along every axis");
    }
    object.finish();
}

// A unit quaternion [x, y, z, w] (glTF's order), or Euler angles in degrees applied about x,
// then y, then z (fixed axes).
void readRotation(Object& object, MeshObjectSpec& mesh) {
    const auto quaternion = object.optional("rotation");
    const auto euler = object.optional("rotate_deg");
    if (quaternion && euler) euler->fail("give either \"rotation\" or \"rotate_deg\", not both");
    if (quaternion) {
        const std::vector<Value> q = quaternion->elements("an array of 4 numbers [x, y, z, w]", 4);
        if (q.size() != 4) quaternion->failExpected("an array of 4 numbers [x, y, z, w]");
        const glm::quat r(q[3].floatNumber(), q[0].floatNumber(), q[1].floatNumber(),
                          q[2].floatNumber());
        const float length = glm::length(r);
        if (!(std::abs(length - 1.0f) < 1e-3f))
            quaternion->fail("expected a unit quaternion (length within 1e-3 of 1), got length " +
                             std::to_string(length));
        mesh.rotation = glm::normalize(r);
    } else if (euler) {
        const glm::vec3 deg = euler->vec3();
        mesh.rotation = glm::angleAxis(glm::radians(deg.z), glm::vec3(0, 0, 1)) *
                        glm::angleAxis(glm::radians(deg.y), glm::vec3(0, 1, 0)) *
                        glm::angleAxis(glm::radians(deg.x), glm::vec3(1, 0, 0));
    }
}

JellyPokeSpec readPoke(const Value& value) {
    Object object(value, "a poke");
    JellyPokeSpec p;
    p.time = object.required("time", "seconds >= 0").number(Range::atLeast(0.0));
    p.position = object.required("position", "an array of 3 numbers [x, y, z]").vec3();
    if (auto r = object.optional("radius")) p.radius = r->floatNumber(Range::greaterThan(0.0));
    p.velocity = object.required("velocity", "an array of 3 numbers [x, y, z]").vec3();
    object.finish();
    return p;
}

JellySpec readJelly(Object& object) {
    JellySpec j;
    if (auto m = object.optional("mass")) j.mass = m->floatNumber(Range::greaterThan(0.0));
    if (auto k = object.optional("stiffness"))
        j.stiffness = k->floatNumber(Range::greaterThan(0.0));
    if (auto k = object.optional("bend_stiffness"))
        j.bendStiffness = k->floatNumber(Range::atLeast(0.0));
    if (auto k = object.optional("volume_stiffness"))
        j.volumeStiffness = k->floatNumber(Range::atLeast(0.0));
    if (auto d = object.optional("damping")) j.damping = d->floatNumber(Range::atLeast(0.0));
    if (auto g = object.optional("gravity")) j.gravity = g->vec3();
    if (auto f = object.optional("floor")) j.floorY = f->floatNumber();
    if (auto f = object.optional("friction")) j.friction = f->floatNumber(Range::atLeast(0.0));
    if (auto n = object.optional("substeps")) j.substeps = int(n->integer(1, 10000));
    if (auto pokes = object.optional("pokes"))
        for (const Value& p : pokes->elements("an array of pokes")) j.pokes.push_back(readPoke(p));
    return j;
}

ArapHandleSpec readHandle(const Value& value) {
    Object object(value, "a handle");
    ArapHandleSpec h;
    h.name = object.required("name", "a non-empty string").nonEmptyString();
    const auto sphere = object.optional("sphere");
    const auto box = object.optional("box");
    if (sphere && box) box->fail("give either \"sphere\" or \"box\", not both");
    if (!sphere && !box) object.failAt("sphere", "a handle needs a region: \"sphere\" or \"box\"");
    if (sphere) {
        Object region(*sphere, "a sphere region");
        h.center = region.required("center", "an array of 3 numbers [x, y, z]").vec3();
        h.radius = region.required("radius", "a number > 0").floatNumber(Range::greaterThan(0.0));
        region.finish();
    } else {
        Object region(*box, "a box region");
        h.sphere = false;
        h.boxMin = region.required("min", "an array of 3 numbers [x, y, z]").vec3();
        const Value max = region.required("max", "an array of 3 numbers [x, y, z]");
        h.boxMax = max.vec3();
        if (!(h.boxMin.x < h.boxMax.x && h.boxMin.y < h.boxMax.y && h.boxMin.z < h.boxMax.z))
            max.fail("expected max > min along every axis");
        region.finish();
        h.center = 0.5f * (h.boxMin + h.boxMax);
    }
    // A handle starts where its region is; tracks move it from there.
    object.finish();
    return h;
}

ArapSpec readArap(Object& object) {
    ArapSpec a;
    if (auto n = object.optional("iterations")) a.iterations = int(n->integer(1, 100));
    const Value handles = object.required("handles", "an array of handles");
    for (const Value& h : handles.elements("an array of handles")) {
        ArapHandleSpec handle = readHandle(h);
        for (const ArapHandleSpec& other : a.handles)
            if (other.name == handle.name)
                h.child("name").fail("duplicate handle name \"" + handle.name + "\"");
        a.handles.push_back(std::move(handle));
    }
    if (a.handles.empty())
        handles.fail("an ARAP deformer needs at least one handle (a fixed one holds the mesh)");
    return a;
}

void readDeformer(const Value& value, MeshObjectSpec& mesh) {
    Object object(value, "a deformer");
    const std::string type =
        object.required("type", "\"jelly\" or \"arap\"").choice({"jelly", "arap"});
    if (type == "jelly") {
        object.setKind("a jelly deformer");
        mesh.jelly = readJelly(object);
    } else {
        object.setKind("an ARAP deformer");
        mesh.arap = readArap(object);
    }
    object.finish();
}

// A VDB or NanoVDB file is a level set: by content when the file is there (core/file_kind.h),
// else by its extension, so that a missing file is reported by the reader that needs it.
bool isVolumeFile(const std::string& path) {
    try {
        const FileKind kind = sniffFileKind(path);
        return kind == FileKind::Vdb || kind == FileKind::NanoVdb;
    } catch (const Error&) {
        std::string ext = std::filesystem::path(path).extension().string();
        for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
        return ext == ".vdb" || ext == ".nvdb";
    }
}

// "grid": a name, or an index in the file.
GridChoice readGridChoice(const Value& value) {
    GridChoice choice;
    if (value.isNumber())
        choice.index = int(value.integer(0, 1000000));
    else
        choice.name = value.nonEmptyString();
    return choice;
}

void readBlur(const Value& value, MeshObjectSpec& mesh) {
    Object object(value, "the index blur");
    if (auto s = object.optional("sigma_voxels"))
        mesh.blurSigmaVoxels = s->floatNumber(Range::openClosed(0.0, 8.0));
    if (auto r = object.optional("radius_voxels"))
        mesh.blurRadiusVoxels = int(r->integer(0, kMaxBlurRadius));
    object.finish();
}

MeshObjectSpec readMesh(const Value& value, const std::filesystem::path& sceneDirectory,
                        MaterialSpec& optics, std::string& containerName) {
    Object object(value, "a mesh");
    MeshObjectSpec mesh;
    mesh.jsonPath = value.pointer();
    const Value name = object.required("name", "a non-empty string of letters, digits, '_', '-'");
    mesh.name = name.nonEmptyString();
    if (!std::all_of(mesh.name.begin(), mesh.name.end(), isNameCharacter))
        name.failExpected("a non-empty string of letters, digits, '_', '-'");
    const auto file = object.optional("file");
    const auto shape = object.optional("shape");
    if (file && shape) shape->fail("give either \"file\" or \"shape\", not both");
    if (!file && !shape) object.failAt("file", "a mesh needs \"file\" or \"shape\"");
    if (file) {
        mesh.shape = MeshShapeType::File;
        mesh.file = scene_detail::resolveAgainst(sceneDirectory, file->nonEmptyString());
        if (isVolumeFile(mesh.file)) {
            mesh.shape = MeshShapeType::LevelSet;
            if (auto grid = object.optional("grid")) mesh.grid = readGridChoice(*grid);
            if (auto holes = object.optional("close_holes"))
                holes->fail("\"close_holes\" applies to triangle meshes; a level set is closed");
        } else {
            if (auto holes = object.optional("close_holes"))
                mesh.closeHolesUpTo = int(holes->integer(0, 1000000));
            if (auto grid = object.optional("grid"))
                grid->fail("\"grid\" picks a level set's grid in a VDB file; " + mesh.file +
                           " is not one");
        }
    } else {
        readShape(*shape, mesh, containerName);
        if (auto holes = object.optional("close_holes"))
            holes->fail("\"close_holes\" applies to meshes read from a file");
    }
    if (mesh.shape == MeshShapeType::Liquid)
        for (const char* key : {"translate", "rotation", "rotate_deg", "scale"})
            if (auto placed = object.optional(key))
                placed->fail(
                    "a liquid stands in its container and takes the container's "
                    "placement; place the container instead");
    if (auto t = object.optional("translate")) mesh.translation = t->vec3();
    readRotation(object, mesh);
    if (auto s = object.optional("scale")) {
        mesh.scale = s->isNumber() ? glm::vec3(s->floatNumber(Range::greaterThan(0.0)))
                                   : s->vec3(Range::greaterThan(0.0));
    }
    if (auto blur = object.optional("blur")) readBlur(*blur, mesh);
    if (auto deformer = object.optional("deformer")) {
        if (mesh.shape == MeshShapeType::Water)
            deformer->fail("a water shape moves by its own equation; it takes no deformer");
        if (mesh.shape == MeshShapeType::Liquid)
            deformer->fail("a liquid follows its container's shape; it takes no deformer");
        if (mesh.shape == MeshShapeType::LevelSet)
            deformer->fail(
                "a level set takes no deformer (deformers move triangles); convert it to a "
                "mesh first");
        readDeformer(*deformer, mesh);
    }

    optics.name = mesh.name;
    const auto ior = object.optional("ior");
    if (ior) optics.ior = ior->floatNumber(Range::atLeast(1.0));
    scene_detail::readDispersion(object, optics, ior.has_value());
    if (auto a = object.optional("absorption")) optics.absorption = a->vec3(Range::atLeast(0.0));
    if (auto s = object.optional("scattering")) optics.scattering = s->vec3(Range::atLeast(0.0));
    if (auto g = object.optional("g")) optics.g = g->floatNumber(Range::open(-1.0, 1.0));
    if (auto e = object.optional("emission")) optics.emission = e->vec3(Range::atLeast(0.0));
    object.finish();
    return mesh;
}

// The container is an earlier mesh (so the liquid, later, displaces the glass where their voxels
// overlap) whose shape stays put: a simulated or deformed one would need the liquid re-made
// every frame, which is not done.
void resolveContainer(const Value& at, const std::string& name,
                      const std::vector<MeshObjectSpec>& earlier, MeshObjectSpec& liquid) {
    const auto it = std::find_if(earlier.begin(), earlier.end(),
                                 [&](const MeshObjectSpec& m) { return m.name == name; });
    if (it == earlier.end())
        at.fail("no earlier mesh is named \"" + name +
                "\" (a liquid's container must come before it in \"meshes\")");
    if (it->shape == MeshShapeType::Water || it->shape == MeshShapeType::Liquid ||
        it->shape == MeshShapeType::LevelSet)
        at.fail("mesh \"" + name + "\" is " +
                (it->shape == MeshShapeType::Water    ? "water"
                 : it->shape == MeshShapeType::Liquid ? "a liquid"
                                                      : "a level set") +
                ", not a container (a container is a triangle mesh whose cavity is filled)");
    if (it->jelly || it->arap)
        at.fail("mesh \"" + name +
                "\" has a deformer: a liquid in a deforming container is "
                "not supported");
    liquid.container = int(it - earlier.begin());  // its placement: core/mesh_placement.h
}

}  // namespace

ParsedMeshes readMeshes(const Value& value, const std::filesystem::path& sceneDirectory) {
    ParsedMeshes out;
    const std::vector<Value> elements = value.elements("an array of meshes", kMaxMeshes);
    for (std::size_t i = 0; i < elements.size(); ++i) {
        MaterialSpec optics;
        std::string containerName;
        MeshObjectSpec mesh = readMesh(elements[i], sceneDirectory, optics, containerName);
        for (std::size_t j = 0; j < out.meshes.size(); ++j)
            if (out.meshes[j].name == mesh.name)
                elements[i].child("name").fail("duplicate mesh name \"" + mesh.name +
                                               "\" (already used by " + elements[j].pointer() +
                                               ")");
        if (mesh.shape == MeshShapeType::Liquid)
            resolveContainer(elements[i].child("shape").child("container"), containerName,
                             out.meshes, mesh);
        const MeshFieldNames fields = meshMaterialFieldNames(mesh);
        const bool volumetric = optics.absorption != glm::vec3(0.0f) ||
                                optics.scattering != glm::vec3(0.0f) ||
                                optics.emission != glm::vec3(0.0f);
        if (!volumetric && optics.ior == 1.0f)
            elements[i].fail(
                "a mesh needs optics: \"ior\" > 1, \"absorption\", \"scattering\" or "
                "\"emission\"");
        if (volumetric) {
            MaterialSpec coverage = optics;
            coverage.field = fields.coverage;
            coverage.ior = 1.0f;
            out.materials.push_back(coverage);
        }
        if (optics.ior != 1.0f) {
            MaterialSpec index;
            index.name = mesh.name + ".n";
            index.field = fields.index;
            index.ior = optics.ior;
            index.abbe = optics.abbe;
            out.materials.push_back(index);
        }
        out.meshes.push_back(std::move(mesh));
    }
    return out;
}

MeshFieldNames meshMaterialFieldNames(const MeshObjectSpec& mesh) {
    // ':' cannot appear in the field names sources write, so these never clash with them.
    return {"mesh:" + mesh.name, "mesh:" + mesh.name + ":n"};
}

int meshOfField(const Scene& scene, const std::string& field) {
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const MeshFieldNames names = meshMaterialFieldNames(scene.meshes[m]);
        if (field == names.coverage || field == names.index) return int(m);
    }
    return -1;
}

}  // namespace eikon
