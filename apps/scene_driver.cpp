#include "apps/scene_driver.h"

#include "core/error.h"
#include "core/mesh_placement.h"
#include "sim/container_fill.h"
#include "sim/refractive_mesh.h"
#include "sim/smoke_from_scene.h"
#include "sim/smoke_publish.h"

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
        Simulated s;
        s.mesh = m;
        if (spec.shape == MeshShapeType::Water) {
            s.water =
                std::make_unique<sim::WaterSurface>(sim::waterSettings(spec.water, scene.time.fps));
        } else if (spec.jelly) {
            // The jelly lives in the world, starting where the mesh is placed.
            s.jelly = std::make_unique<sim::Jelly>(placeMesh(local, spec),
                                                   sim::jellySettings(*spec.jelly, scene.time.fps));
        } else if (spec.arap) {
            // Dragged in object space: the placement still applies (and may be animated).
            s.arap = std::make_unique<sim::ArapDrag>(local, *spec.arap,
                                                     scene.path + ":" + spec.jsonPath);
            s.dragOffsets.assign(spec.arap->handles.size(), glm::vec3(0.0f));
        } else if (spec.shape == MeshShapeType::File) {
            fixedMeshes_.emplace_back(m, std::move(local));
        } else if (spec.shape == MeshShapeType::Liquid) {
            // Made from the container's object-space mesh, so it shares its placement.
            const size_t container = size_t(spec.container);
            TriangleMesh containerMesh = meshShape(scene.meshes[container]);
            for (const auto& [c, mesh] : fixedMeshes_)
                if (c == container) containerMesh = mesh;
            fixedMeshes_.emplace_back(
                m, fillContainer(containerMesh, spec.fill, scene.path + ":" + spec.jsonPath).mesh);
        }
        if (s.water || s.jelly || s.arap) simulated_.push_back(std::move(s));
    }
    for (const SourceSpec& source : scene.sources)
        if (source.type == SourceType::Simulation && !smokeScene_)
            smokeScene_ = std::make_unique<Scene>(scene);
}

void SceneDriver::stepSmoke(FrameRenderer& renderer, int frame) {
    const Scene& scene = *smokeScene_;
    const int first = scene.time.frameStart;
    if (frame < first)
        throw Error(scene.path + ":/time/frame_start",
                    "the simulation starts at frame " + std::to_string(first) + "; frame " +
                        std::to_string(frame) + " comes before it");
    if (smoke_ && smokeFrame_ == frame) return;
    if (!smoke_ || frame < smokeFrame_) {
        smoke_ = std::make_unique<sim::SmokeSolver>(sim::smokeSolverFrom(scene));
        smokeFrame_ = first - 1;
    }
    while (smokeFrame_ < frame) {
        smoke_->advanceFrame();
        ++smokeFrame_;
    }
    sim::publishSmoke(smoke_->grid(), renderer.publishedFields(),
                      scene.path + ": simulation frame " + std::to_string(frame));
}

void SceneDriver::prepareFrame(FrameRenderer& renderer, int frame) {
    if (!fixedMeshesSet_) {
        for (const auto& [m, mesh] : fixedMeshes_) renderer.setMesh(m, mesh);
        fixedMeshesSet_ = true;
    }
    if (!animation_.empty()) animation_.apply(clock_.timeOfFrame(frame), renderer.scene());
    if (smokeScene_) stepSmoke(renderer, frame);
    for (Simulated& s : simulated_) {
        if (s.frameSet == frame) continue;
        if (s.water) {
            s.water->advanceToFrame(frame);
            renderer.setMesh(s.mesh, s.water->mesh());
        } else if (s.jelly) {
            s.jelly->advanceToFrame(frame);
            renderer.setMesh(s.mesh, unplaceMesh(s.jelly->mesh(), renderer.scene().meshes[s.mesh]));
        } else {
            // Frames before this one need their own handle positions: the tracks evaluated on a
            // copy of the scene at each frame's time.
            const Scene& now = renderer.scene();
            s.arap->advanceToFrame(frame, [&](int k) {
                if (k == frame || animation_.empty()) return withDrags(now, s);
                Scene then = now;
                animation_.apply(clock_.timeOfFrame(k), then);
                return withDrags(then, s);
            });
            renderer.setMesh(s.mesh, s.arap->mesh());
        }
        s.frameSet = frame;
    }
}

ArapSpec SceneDriver::withDrags(const Scene& scene, const Simulated& s) {
    ArapSpec spec = *scene.meshes[s.mesh].arap;
    for (size_t j = 0; j < spec.handles.size() && j < s.dragOffsets.size(); ++j)
        spec.handles[j].translation += s.dragOffsets[j];
    return spec;
}

SceneDriver::Simulated& SceneDriver::arapOf(size_t mesh) {
    for (Simulated& s : simulated_)
        if (s.arap && s.mesh == mesh) return s;
    throw Error("mesh " + std::to_string(mesh), "has no ARAP deformer to drag");
}

std::vector<SceneDriver::HandleRef> SceneDriver::arapHandles() const {
    std::vector<HandleRef> handles;
    for (const Simulated& s : simulated_)
        if (s.arap)
            for (size_t j = 0; j < s.dragOffsets.size(); ++j) handles.push_back({s.mesh, j});
    return handles;
}

glm::vec3 SceneDriver::handleCentre(const FrameRenderer& renderer, HandleRef h) const {
    const Simulated& s = arapOf(h.mesh);
    const std::vector<std::uint32_t>& vertices = s.arap->handleVertices()[h.handle];
    glm::vec3 sum(0.0f);
    for (std::uint32_t v : vertices) sum += s.arap->positions()[v];
    return placePoint(sum / float(vertices.size()), placementOf(renderer.scene(), h.mesh));
}

void SceneDriver::dragHandle(FrameRenderer& renderer, HandleRef h, glm::vec3 worldMotion) {
    Simulated& s = arapOf(h.mesh);
    s.dragOffsets[h.handle] += unplaceMotion(worldMotion, placementOf(renderer.scene(), h.mesh));
    s.arap->dragCurrentFrame(withDrags(renderer.scene(), s));
    renderer.setMesh(s.mesh, s.arap->mesh());
}

glm::vec3 SceneDriver::handleTranslation(const FrameRenderer& renderer, HandleRef h) const {
    return withDrags(renderer.scene(), arapOf(h.mesh)).handles[h.handle].translation;
}

}  // namespace eikon::app
