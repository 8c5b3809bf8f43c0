#include "pipeline/scene_driver.h"

#include "core/error.h"
#include "core/mesh_placement.h"
#include "sim/container_fill.h"
#include "sim/refractive_mesh.h"

namespace eikon {

SceneDriver::SceneDriver(const Scene& scene, bool simulationFromCache)
    : animation_(scene), clock_(scene.time.fps, 1.0) {
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const MeshObjectSpec& spec = scene.meshes[m];
        TriangleMesh local = meshShape(spec);
        if (spec.shape == MeshShapeType::File) {
            RefractiveMeshOptions options;
            options.closeHolesUpTo = std::size_t(spec.closeHolesUpTo);
            local = loadRefractiveMesh(spec.file, options).mesh;
        }
        if (std::unique_ptr<sim::MovingMesh> moving = sim::makeMovingMesh(scene, m, local)) {
            moving_.push_back({std::move(moving)});
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
    }
    fieldSimulations_ = sim::makeFieldSimulations(scene, simulationFromCache);
}

FrameInputs SceneDriver::frameInputs(int frame, const Scene& base) {
    FrameInputs inputs;
    inputs.frame = frame;
    inputs.scene = base;
    if (!fixedMeshesSet_) {
        inputs.meshes = fixedMeshes_;
        fixedMeshesSet_ = true;
    }
    if (!animation_.empty()) animation_.apply(clock_.timeOfFrame(frame), inputs.scene);
    for (const auto& simulation : fieldSimulations_)
        if (simulation->advanceToFrame(frame))
            simulation->publish(inputs.fields,
                                base.path + ": simulation frame " + std::to_string(frame));
    const Scene& now = inputs.scene;
    // An earlier frame's scene, for deformers solved frame by frame from their start; none is
    // needed when no track moves anything.
    sim::SceneAtFrame earlier;
    if (!animation_.empty())
        earlier = [&](int k) {
            Scene then = base;
            animation_.apply(clock_.timeOfFrame(k), then);
            return then;
        };
    for (Moving& m : moving_) {
        if (m.frameSet == frame) continue;
        m.mesh->advanceToFrame(frame, now, earlier);
        inputs.meshes.emplace_back(m.mesh->meshIndex(), m.mesh->objectSpaceMesh(now));
        m.frameSet = frame;
    }
    prepared_ = now;
    return inputs;
}

const Scene& SceneDriver::preparedScene() const {
    if (!prepared_) throw Error("ARAP handles", "no frame prepared yet");
    return *prepared_;
}

sim::ArapMovingMesh& SceneDriver::arapOf(size_t mesh) {
    for (Moving& m : moving_)
        if (auto* arap = dynamic_cast<sim::ArapMovingMesh*>(m.mesh.get()))
            if (arap->meshIndex() == mesh) return *arap;
    throw Error("mesh " + std::to_string(mesh), "has no ARAP deformer to drag");
}

std::vector<SceneDriver::HandleRef> SceneDriver::arapHandles() const {
    std::vector<HandleRef> handles;
    for (const Moving& m : moving_)
        if (const auto* arap = dynamic_cast<const sim::ArapMovingMesh*>(m.mesh.get()))
            for (size_t j = 0; j < arap->handleCount(); ++j)
                handles.push_back({arap->meshIndex(), j});
    return handles;
}

glm::vec3 SceneDriver::handleCentre(HandleRef h) const {
    const sim::ArapDrag& arap = arapOf(h.mesh).deformer();
    const std::vector<std::uint32_t>& vertices = arap.handleVertices()[h.handle];
    glm::vec3 sum(0.0f);
    for (std::uint32_t v : vertices) sum += arap.positions()[v];
    return placePoint(sum / float(vertices.size()), placementOf(preparedScene(), h.mesh));
}

void SceneDriver::dragHandle(HandleRef h, glm::vec3 worldMotion, FrameInputs& inputs) {
    const Scene& scene = preparedScene();
    sim::ArapMovingMesh& arap = arapOf(h.mesh);
    arap.drag(h.handle, unplaceMotion(worldMotion, placementOf(scene, h.mesh)), scene);
    inputs.meshes.emplace_back(h.mesh, arap.objectSpaceMesh(scene));
}

glm::vec3 SceneDriver::handleTranslation(HandleRef h) const {
    return arapOf(h.mesh).withDrags(preparedScene()).handles[h.handle].translation;
}

}  // namespace eikon
