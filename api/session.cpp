#include <filesystem>

#include "api/rendered_image.h"
#include "api/session_impl.h"
#include "api/shader_location.h"
#include "core/dispersion.h"
#include "core/error.h"
#include "core/particle_color.h"
#include "core/transfer_function.h"
#include "pipeline/scene_input.h"
#include "render/image.h"

namespace fs = std::filesystem;

namespace eikon {
namespace {

glm::vec3 toGlm(const Vec3& v) {
    return {v[0], v[1], v[2]};
}
Vec3 fromGlm(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

std::string deviceName(Device d) {
    return d == Device::Gpu ? "gpu" : d == Device::Cpu ? "cpu" : "auto";
}

void mergeFields(const FieldRegistry& from, FieldRegistry& into) {
    for (const std::string& name : from.names()) {
        const Field& f = from.get(name);
        into.set(name, f.grid, f.origin);
    }
}

MaterialSpec& materialNamed(Scene& scene, const std::string& name) {
    for (MaterialSpec& m : scene.materials)
        if (m.name == name) return m;
    std::string names;
    for (const MaterialSpec& m : scene.materials) names += (names.empty() ? "" : ", ") + m.name;
    throw Error("material '" + name + "'", "no material of that name (the scene has: " +
                                               (names.empty() ? "none" : names) + ")");
}

}  // namespace

Session::Impl::Impl(Scene scene, Device device)
    : base(std::move(scene)), backend((useInstalledShaders(), chooseBackend(deviceName(device)))) {
    driver = std::make_unique<SceneDriver>(base);
    renderer = std::make_unique<FrameRenderer>(base, backend.backend, backend.context.get());
}

FrameInputs Session::Impl::step(int frame) {
    FrameInputs inputs = driver->frameInputs(frame, base);
    mergeFields(inputs.fields, steppedFields);
    steppedFrame = frame;
    // Earlier handovers first, so a mesh moved again replaces its older shape.
    std::vector<std::pair<size_t, TriangleMesh>> meshes = std::move(pendingMeshes);
    for (auto& m : inputs.meshes) meshes.push_back(std::move(m));
    inputs.meshes = std::move(meshes);
    mergeFields(inputs.fields, pendingFields);
    inputs.fields = FieldRegistry();
    mergeFields(pendingFields, inputs.fields);
    pendingMeshes.clear();
    pendingFields.clear();
    return inputs;
}

Session::Session(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Session::Session(Session&&) noexcept = default;
Session& Session::operator=(Session&&) noexcept = default;
Session::~Session() = default;

Session Session::open(const std::string& path, Device device) {
    SceneInput input = readSceneInput(path, InputChoices{});
    return Session(std::make_unique<Impl>(std::move(input.scene), device));
}

Session Session::fromJson(const std::string& json, const std::string& baseDirectory,
                          Device device) {
    // Messages name the JSON as a file in baseDirectory, where its relative paths start.
    const std::string file = (fs::path(baseDirectory) / "<json text>").string();
    return Session(std::make_unique<Impl>(parseScene(json, file), device));
}

int Session::firstFrame() const {
    return impl_->base.time.frameStart;
}
int Session::lastFrame() const {
    return impl_->base.time.frameEnd;
}
std::string Session::deviceDescription() const {
    return impl_->backend.description;
}

void Session::stepTo(int frame) {
    FrameInputs inputs = impl_->step(frame);
    // Kept for the next render: nothing reaches the renderer before it.
    impl_->pendingMeshes = std::move(inputs.meshes);
    mergeFields(inputs.fields, impl_->pendingFields);
}

RenderedImage Session::render(int frame) {
    const FrameInputs inputs = impl_->step(frame);
    const Image image = impl_->renderer->render(inputs);
    RenderedImage out = linearPartsOf(image);
    out.frame = frame;
    const RenderSettings& r = inputs.scene.render;
    out.exposure = r.exposure;
    out.toneCurve = r.toneCurve == ToneCurve::Filmic ? 1 : 0;
    out.srgb8 = toneMapToSrgb8(image, r.exposure, r.toneCurve);
    return out;
}

void RenderedImage::write(const std::string& path) const {
    Image image(width, height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = glm::vec4(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], transmittance[i]);
    if (fs::path(path).extension() == ".exr")
        writeExr(path, image);
    else
        writePng(path, image, exposure, toneCurve == 1 ? ToneCurve::Filmic : ToneCurve::Linear);
}

Camera Session::camera() const {
    const CameraSpec& c = impl_->base.camera;
    return {fromGlm(c.position), fromGlm(c.lookAt), fromGlm(c.up), c.horizontalFovDeg};
}

void Session::setCamera(const Camera& camera) {
    if (!(camera.horizontalFovDegrees > 0.0f && camera.horizontalFovDegrees < 180.0f))
        throw Error("camera", "the horizontal field of view must be in (0, 180) degrees, got " +
                                  std::to_string(camera.horizontalFovDegrees));
    CameraSpec& c = impl_->base.camera;
    c.automatic = false;
    c.position = toGlm(camera.position);
    c.lookAt = toGlm(camera.lookAt);
    c.up = toGlm(camera.up);
    c.horizontalFovDeg = camera.horizontalFovDegrees;
}

void Session::setImageSize(int width, int height) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw Error("image size", "expected 1 to 16384 pixels a side, got " +
                                      std::to_string(width) + "x" + std::to_string(height));
    impl_->base.render.width = width;
    impl_->base.render.height = height;
}

std::size_t Session::lightCount() const {
    return impl_->base.lights.size();
}

Light Session::light(std::size_t index) const {
    if (index >= lightCount())
        throw Error("light " + std::to_string(index),
                    "the scene has " + std::to_string(lightCount()) + " light(s)");
    const LightSpec& l = impl_->base.lights[index];
    Light out;
    out.kind = l.type == LightType::Point         ? LightKind::Point
               : l.type == LightType::Directional ? LightKind::Directional
                                                  : LightKind::Spot;
    out.position = fromGlm(l.position);
    out.direction = fromGlm(l.direction);
    out.color = fromGlm(l.color);
    out.intensity = l.intensity;
    out.coneAngleDegrees = l.coneAngleDeg;
    out.coneSoftnessDegrees = l.coneSoftnessDeg;
    out.angularDiameterDegrees = l.angularDiameterDeg;
    return out;
}

void Session::setLight(std::size_t index, const Light& light) {
    (void)this->light(index);  // the index check
    if (!(light.intensity >= 0.0f))
        throw Error("light " + std::to_string(index), "intensity must be >= 0");
    if (!(light.angularDiameterDegrees >= 0.0f &&
          light.angularDiameterDegrees <= kMaxAngularDiameterDeg) ||
        (light.kind != LightKind::Directional && light.angularDiameterDegrees != 0.0f))
        throw Error("light " + std::to_string(index),
                    "angular_diameter_degrees must be in [0, 30], and 0 but for a directional "
                    "light");
    LightSpec& l = impl_->base.lights[index];
    l.type = light.kind == LightKind::Point         ? LightType::Point
             : light.kind == LightKind::Directional ? LightType::Directional
                                                    : LightType::Spot;
    l.position = toGlm(light.position);
    l.direction = toGlm(light.direction);
    l.color = toGlm(light.color);
    l.intensity = light.intensity;
    l.coneAngleDeg = light.coneAngleDegrees;
    l.coneSoftnessDeg = light.coneSoftnessDegrees;
    l.angularDiameterDeg = light.angularDiameterDegrees;
}

std::vector<std::string> Session::materialNames() const {
    std::vector<std::string> names;
    for (const MaterialSpec& m : impl_->base.materials) names.push_back(m.name);
    return names;
}

Material Session::material(const std::string& name) const {
    const MaterialSpec& m = materialNamed(impl_->base, name);
    Material out{m.name,
                 m.field,
                 fromGlm(m.absorption),
                 fromGlm(m.scattering),
                 m.g,
                 fromGlm(m.emission),
                 m.ior,
                 m.abbe,
                 {},
                 m.particleColor.map,
                 {m.particleColor.range.x, m.particleColor.range.y},
                 {}};
    for (const glm::vec2& p : m.transfer) out.transfer.push_back({p.x, p.y});
    for (const glm::vec4& p : m.particleColor.points)
        out.particleColorPoints.push_back({p.x, p.y, p.z, p.w});
    return out;
}

void Session::setMaterial(const Material& material) {
    MaterialSpec& m = materialNamed(impl_->base, material.name);
    const std::string where = "material '" + material.name + "'";
    for (float v : {material.absorption[0], material.absorption[1], material.absorption[2],
                    material.scattering[0], material.scattering[1], material.scattering[2]})
        if (!(v >= 0.0f)) throw Error(where, "absorption and scattering must be >= 0");
    if (!(material.anisotropy > -1.0f && material.anisotropy < 1.0f))
        throw Error(where, "anisotropy must be in (-1, 1)");
    if (!(material.ior >= 1.0f) && m.gladstoneDale <= 0.0f) throw Error(where, "ior must be >= 1");
    // As the scene's "abbe" (core/scene_dispersion.cpp).
    if (!(material.abbe >= 0.0f)) throw Error(where, "abbe must be > 0, or 0 for no dispersion");
    if (material.abbe > 0.0f && (m.gladstoneDale > 0.0f || !(material.ior > 1.0f)))
        throw Error(where, "abbe needs a glass or a liquid: ior above 1");
    if (material.abbe > 0.0f && !(channelIndices(material.ior, material.abbe).x >= 1.0f))
        throw Error(where, "abbe gives an index below vacuum's in the red channel");
    std::vector<glm::vec2> transfer;
    for (const std::array<float, 2>& p : material.transfer) transfer.emplace_back(p[0], p[1]);
    // As the scene's "transfer" (core/scene_transfer.cpp).
    if (!transfer.empty() && m.gladstoneDale > 0.0f)
        throw Error(where, "a Gladstone–Dale material takes no transfer function");
    if (!transfer.empty()) {
        const std::string problem = transferFunctionProblem(transfer);
        if (!problem.empty()) throw Error(where, "the transfer function " + problem);
    }
    // As the scene's "particle_color" (core/scene_transfer.cpp).
    ParticleColorSpec color;
    color.map = material.particleColorMap;
    color.range = glm::vec2(material.particleColorRange[0], material.particleColorRange[1]);
    if (color.map.empty())
        for (const std::array<float, 4>& p : material.particleColorPoints)
            color.points.emplace_back(p[0], p[1], p[2], p[3]);
    else if (!material.particleColorPoints.empty())
        throw Error(where, "give a particle colour map or particle colour points, not both");
    if (!color.empty()) {
        const std::string problem = particleColorProblem(color);
        if (!problem.empty()) throw Error(where, "the particle colour " + problem);
    }
    m.absorption = toGlm(material.absorption);
    m.scattering = toGlm(material.scattering);
    m.g = material.anisotropy;
    m.emission = toGlm(material.emission);
    if (m.gladstoneDale <= 0.0f) m.ior = material.ior;
    m.abbe = material.abbe;
    m.transfer = transfer;
    m.particleColor = color;
}

}  // namespace eikon
