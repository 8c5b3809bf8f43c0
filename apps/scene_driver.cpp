#include "apps/scene_driver.h"

#include "core/mesh_placement.h"
#include "sim/container_fill.h"
#include "sim/refractive_mesh.h"

namespace eikon::app {

SceneDriver::SceneDriver(const Scene& scene) : animation_(scene), clock_(scene.time.fps, 1.0) {
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const MeshObjectSpec& spec = scene.meshes[m];
        TriangleMesh local = meshShape(spec);
        if (spec.shape == MeshShapeType::File) {
            RefractiveMeshOptions options;
            options.closeHolesUpTo = std::size_t(spec.closeHolesUpTo);
            local = loadRefractiveMesh(spec.file, options).mesh;
        }
        if (spec.shape == MeshShapeType::Water) {
            Simulated s{m, std::make_unique<sim::WaterSurface>(
                               sim::waterSettings(spec.water, scene.time.fps)),
                        nullptr};
            simulated_.push_back(std::move(s));
        } else if (spec.jelly) {
            // The jelly lives in the world, starting where the mesh is placed.
            const TriangleMesh world = placeMesh(local, spec);
            Simulated s{m, nullptr,
                        std::make_unique<sim::Jelly>(
                            world, sim::jellySettings(*spec.jelly, scene.time.fps))};
            simulated_.push_back(std::move(s));
        } else if (spec.shape == MeshShapeType::File) {
            fixedMeshes_.emplace_back(m, std::move(local));
        } else if (spec.shape == MeshShapeType::Liquid) {
            // Made from the container's object-space mesh, so it shares its placement.
            const size_t container = size_t(spec.container);
            TriangleMesh containerMesh = meshShape(scene.meshes[container]);
            for (const auto& [c, mesh] : fixedMeshes_)
                if (c == container) containerMesh = mesh;
            fixedMeshes_.emplace_back(
                m, fillContainer(containerMesh, spec.fill, scene.path + ":" + spec.jsonPath)
                       .mesh);
        }
    }
}

void SceneDriver::prepareFrame(FrameRenderer& renderer, int frame) {
    if (!fixedMeshesSet_) {
        for (const auto& [m, mesh] : fixedMeshes_) renderer.setMesh(m, mesh);
        fixedMeshesSet_ = true;
    }
    if (!animation_.empty()) animation_.apply(clock_.timeOfFrame(frame), renderer.scene());
    for (Simulated& s : simulated_) {
        if (s.frameSet == frame) continue;
        if (s.water) {
            s.water->advanceToFrame(frame);
            renderer.setMesh(s.mesh, s.water->mesh());
        } else {
            s.jelly->advanceToFrame(frame);
            renderer.setMesh(s.mesh, unplaceMesh(s.jelly->mesh(), renderer.scene().meshes[s.mesh]));
        }
        s.frameSet = frame;
    }
}

}  // namespace eikon::app
