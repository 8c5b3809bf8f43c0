#include "render/mesh_fields.h"

#include <cstring>

#include "core/error.h"
#include "core/mesh_placement.h"
#include "render/input_key.h"
#include "render/voxelize.h"

namespace eikon {

namespace {

std::vector<unsigned char> placementKey(std::uint64_t version, const MeshObjectSpec& spec) {
    std::vector<unsigned char> key;
    appendBytes(key, &version, sizeof(version));
    appendBytes(key, &spec.scale, sizeof(spec.scale));
    appendBytes(key, &spec.rotation, sizeof(spec.rotation));
    appendBytes(key, &spec.translation, sizeof(spec.translation));
    return key;
}

// The placed box of a level set: its eight corners through the placement.
Bounds3 placedBox(const Bounds3& local, const MeshObjectSpec& placement) {
    Bounds3 out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p = placePoint(
            {corner & 1 ? local.max.x : local.min.x, corner & 2 ? local.max.y : local.min.y,
             corner & 4 ? local.max.z : local.min.z},
            placement);
        out = corner == 0 ? Bounds3{p, p} : Bounds3{glm::min(out.min, p), glm::max(out.max, p)};
    }
    return out;
}

}  // namespace

MeshFields::MeshFields(const Scene& scene) : meshes_(scene.meshes.size()) {
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const MeshShapeType shape = scene.meshes[i].shape;
        if (shape == MeshShapeType::LevelSet) {
            const MeshObjectSpec& spec = scene.meshes[i];
            try {
                meshes_[i].levelSet = LevelSet::read(spec.file, spec.grid);
            } catch (const Error& e) {
                throw Error(scene.path + ":" + spec.jsonPath + "/file",
                            "mesh '" + spec.name + "': " + e.what());
            }
            meshes_[i].loaded = true;
            continue;
        }
        if (shape == MeshShapeType::File || shape == MeshShapeType::Water ||
            shape == MeshShapeType::Liquid)
            continue;
        meshes_[i].local = meshShape(scene.meshes[i]);
        meshes_[i].loaded = true;
    }
}

void MeshFields::setMesh(const Scene& scene, size_t index, TriangleMesh objectSpace) {
    if (index >= meshes_.size())
        throw Error(scene.path, "mesh " + std::to_string(index) +
                                    " does not exist (the scene has " +
                                    std::to_string(meshes_.size()) + ")");
    const MeshObjectSpec& spec = scene.meshes[index];
    const std::string what = scene.path + ":" + spec.jsonPath + " (mesh '" + spec.name + "')";
    checkMeshForVoxelization(objectSpace, what);
    if (objectSpace.triangles.empty()) throw Error(what, "the mesh has no triangles");
    Mesh& m = meshes_[index];
    m.local = std::move(objectSpace);
    m.loaded = true;
    ++m.version;
}

const TriangleMesh& MeshFields::placed(const Scene& scene, size_t index) {
    Mesh& m = meshes_[index];
    const MeshObjectSpec& spec = scene.meshes[index];
    if (!m.loaded && spec.shape == MeshShapeType::Water)
        throw Error(scene.path + ":" + spec.jsonPath + "/shape",
                    "mesh '" + spec.name +
                        "' (water) was never stepped: the program rendering the scene must "
                        "step its surface (sim/water_surface.h) and set the mesh");
    if (!m.loaded && spec.shape == MeshShapeType::Liquid)
        throw Error(scene.path + ":" + spec.jsonPath + "/shape",
                    "mesh '" + spec.name +
                        "' (a liquid) was never made: the program rendering the scene must fill "
                        "its container (sim/container_fill.h) and set the mesh");
    if (!m.loaded)
        throw Error(scene.path + ":" + spec.jsonPath + "/file",
                    "mesh '" + spec.name + "' (" + spec.file +
                        ") was not loaded: the program rendering the scene must read it");
    const MeshObjectSpec& placement = placementOf(scene, index);
    std::vector<unsigned char> key = placementKey(m.version, placement);
    if (key != m.placedKey) {
        m.placed = placeMesh(m.local, placement);
        m.placedKey = std::move(key);
    }
    return m.placed;
}

std::vector<Bounds3> MeshFields::worldBounds(const Scene& scene) {
    if (scene.meshes.size() != meshes_.size())
        throw Error(scene.path + ":/meshes",
                    "meshes cannot be added or removed after rendering "
                    "started (had " +
                        std::to_string(meshes_.size()) + ", now " +
                        std::to_string(scene.meshes.size()) + ")");
    std::vector<Bounds3> out;
    for (size_t i = 0; i < meshes_.size(); ++i) {
        const MeshObjectSpec& spec = scene.meshes[i];
        // Water moves every frame; the volume is framed on the room its waves stay in.
        if (meshes_[i].levelSet)
            out.push_back(placedBox(meshes_[i].levelSet->bounds(), placementOf(scene, i)));
        else
            out.push_back(spec.shape == MeshShapeType::Water
                              ? boundsOf(placeMesh(meshShape(spec), spec))
                              : boundsOf(placed(scene, i)));
    }
    return out;
}

void MeshFields::update(const Scene& scene, const RenderVolume& volume, MeshVoxelizerGpu* gpu,
                        std::map<std::string, DenseGrid>& dense) {
    std::vector<unsigned char> composeKey;  // every coverage's inputs and every blur setting
    for (size_t i = 0; i < meshes_.size(); ++i) {
        Mesh& m = meshes_[i];
        const MeshObjectSpec& spec = scene.meshes[i];
        const TriangleMesh* world = m.levelSet ? nullptr : &placed(scene, i);
        std::vector<unsigned char> key =
            m.levelSet ? placementKey(0, placementOf(scene, i)) : m.placedKey;
        appendBytes(key, &volume.bounds, sizeof(volume.bounds));
        appendBytes(key, &volume.resolution, sizeof(volume.resolution));
        if (key != m.coverageKey && m.levelSet) {
            m.coverage = m.levelSet->coverage(volume, placementOf(scene, i));
            m.coverageKey = key;
            ++voxelizations_;
        } else if (key != m.coverageKey) {
            checkMeshFitsVoxelGrid(*world,
                                   scene.path + ":" + spec.jsonPath + " (mesh '" + spec.name + "')",
                                   volume.bounds.min, volume.voxelSize(), volume.resolution);
            m.coverage =
                gpu ? gpu->voxelizeToHost(*world, volume) : voxelizeCoverageCpu(*world, volume);
            m.coverageKey = key;
            ++voxelizations_;
        }
        composeKey.insert(composeKey.end(), key.begin(), key.end());
        appendBytes(composeKey, &scene.meshes[i].blurSigmaVoxels, sizeof(float));
        appendBytes(composeKey, &scene.meshes[i].blurRadiusVoxels, sizeof(int));
    }
    if (composeKey == composeKey_) return;
    composeKey_ = std::move(composeKey);

    // A later mesh displaces earlier ones: from the last, each keeps the part still free.
    ++composed_;
    std::vector<float> free(volume.voxelCount(), 1.0f);
    for (size_t i = meshes_.size(); i-- > 0;) {
        const MeshObjectSpec& spec = scene.meshes[i];
        const MeshFieldNames names = meshMaterialFieldNames(spec);
        DenseGrid coverage;
        coverage.field = names.coverage;
        coverage.version = composed_;
        coverage.volume = volume;
        coverage.values = meshes_[i].coverage;
        for (size_t v = 0; v < free.size(); ++v) {
            coverage.values[v] *= free[v];
            free[v] *= 1.0f - meshes_[i].coverage[v];
        }
        DenseGrid index = coverage;
        index.field = names.index;
        index.values = blurCoverageCpu(coverage.values, volume.resolution,
                                       {spec.blurSigmaVoxels, spec.blurRadiusVoxels});
        dense[names.coverage] = std::move(coverage);
        dense[names.index] = std::move(index);
    }
}

}  // namespace eikon
