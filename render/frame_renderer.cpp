#include "render/frame_renderer.h"

#include <cstdlib>

#include "core/camera.h"
#include "core/resample.h"
#include "render/gl_context.h"
#include "render/params_buffer.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"
#include "render/view_pass.h"
#include "render/volume_textures.h"

namespace eikon {

namespace {

// Texture-unit filtering where it is exact enough to keep the GPU equal to the CPU twin: on
// software rasterizers (float weights, 2-3x faster there). Hardware GPUs filter with 8-bit
// fractional weights, so they take the 8-tap path unless EIKON_TRILINEAR=hardware asks.
bool useHardwareTrilinear(const GlContext& gl) {
    const char* env = std::getenv("EIKON_TRILINEAR");
    if (env && std::string(env) == "hardware") return true;
    if (env && std::string(env) == "exact") return false;
    return isSoftwareRenderer(gl.rendererName());
}

}  // namespace

FrameRenderer::FrameRenderer(const Scene& scene, Backend backend, GlContext* context)
    : scene_(scene), backend_(backend), sources_(scene_) {
    if (backend_ == Backend::Gpu) {
        if (!context) {
            ownContext_ = createHeadlessContext();
            context = ownContext_.get();
        }
        gl_ = context;
        textures_ = std::make_unique<VolumeTextures>();
        paramsBuffer_ = std::make_unique<ParamsBuffer>();
        hardwareTrilinear_ = useHardwareTrilinear(*gl_);
        lightVolumesGpu_ = std::make_unique<LightVolumesGpu>(hardwareTrilinear_);
        viewPass_ = std::make_unique<ViewPassGpu>(hardwareTrilinear_);
        refractionGpu_ = std::make_unique<RefractionVolumesGpu>();
    }
    timer_ = std::make_unique<GpuStageTimer>(backend_ == Backend::Gpu);
}

FrameRenderer::~FrameRenderer() {
    // GL objects go before the context that owns them.
    timer_.reset();
    viewPass_.reset();
    refractionGpu_.reset();
    lightVolumesGpu_.reset();
    paramsBuffer_.reset();
    textures_.reset();
    ownContext_.reset();
}

namespace {

// The bytes the light volumes depend on: the parameters without camera and image settings, and
// the versions of the field grids. Equal bytes, equal volumes.
std::vector<unsigned char> lightVolumeInputs(const ViewSetup& setup,
                                             const std::vector<const DenseGrid*>& grids) {
    shared::GpuViewParams p = setup.params;
    p.cameraOrigin = p.cameraRight = p.cameraUp = p.cameraForward = glm::vec4(0.0f);
    p.image.x = p.image.y = 0;
    p.background = glm::vec4(0.0f);
    const auto* bytes = reinterpret_cast<const unsigned char*>(&p);
    std::vector<unsigned char> key(bytes, bytes + sizeof(p));
    for (const DenseGrid* g : grids) {
        const auto* v = reinterpret_cast<const unsigned char*>(&g->version);
        key.insert(key.end(), v, v + sizeof(g->version));
    }
    return key;
}

// The bytes the ∇n volume depends on: the volume, the materials' ior and field slots, and the
// versions of the field grids.
std::vector<unsigned char> gradientInputs(const ViewSetup& setup,
                                          const std::vector<const DenseGrid*>& grids) {
    const shared::GpuViewParams& p = setup.params;
    std::vector<float> values = {p.volumeMin.x, p.volumeMin.y, p.volumeMin.z,
                                 p.volumeMax.x, p.volumeMax.y, p.volumeMax.z,
                                 float(p.resolution.x), float(p.resolution.y),
                                 float(p.resolution.z), float(p.resolution.w)};
    for (int m = 0; m < p.resolution.w; ++m) {
        values.push_back(p.materials[m].emission.w);
        values.push_back(float(p.materials[m].slot.x));
    }
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    std::vector<unsigned char> key(bytes, bytes + values.size() * sizeof(float));
    for (const DenseGrid* g : grids) {
        const auto* v = reinterpret_cast<const unsigned char*>(&g->version);
        key.insert(key.end(), v, v + sizeof(g->version));
    }
    return key;
}

}  // namespace

int FrameRenderer::uploads() const {
    return textures_ ? textures_->uploads() : 0;
}

std::vector<StageTime> FrameRenderer::takeStats() {
    std::vector<StageTime> out = timer_->results();
    timer_->reset();
    return out;
}

Image FrameRenderer::render(int frame) {
    timer_->begin("load");
    sources_.loadFrame(frame, fields_);
    timer_->end();

    timer_->begin("resample");
    volume_ = chooseRenderVolume(scene_, fields_);
    const CameraFrame camera =
        makeCameraFrame(scene_.camera, volume_.bounds, scene_.render.width, scene_.render.height);
    const ViewSetup setup = makeViewSetup(scene_, volume_, camera);
    std::vector<const DenseGrid*> slotGrids;
    for (const std::string& name : setup.slotFields) {
        const Field& f = fields_.get(name);
        auto it = dense_.find(name);
        if (it == dense_.end() || it->second.version != f.version || it->second.volume != volume_) {
            dense_[name] = resampleToDense(f, volume_);
            ++resamples_;
        }
        slotGrids.push_back(&dense_[name]);
    }
    timer_->end();

    const bool needLights = viewNeedsLightVolumes(setup);
    std::vector<unsigned char> lightInputs;
    if (needLights) lightInputs = lightVolumeInputs(setup, slotGrids);
    const bool lightsChanged = needLights && lightInputs != lightInputs_;
    const bool curved = setup.params.pipeline.x != 0;
    std::vector<unsigned char> refractionInputs;
    if (curved) refractionInputs = gradientInputs(setup, slotGrids);
    const bool gradientChanged = curved && refractionInputs != gradientInputs_;

    if (backend_ == Backend::Cpu) {
        if (gradientChanged) {
            timer_->begin("gradient");
            gradientCpu_ = computeIndexGradientCpu(setup, slotGrids);
            timer_->end();
            gradientInputs_ = std::move(refractionInputs);
            ++gradientUpdates_;
        }
        if (lightsChanged) {
            timer_->begin("light");
            lightVolumesCpu_ = computeLightVolumesCpu(setup, slotGrids);
            timer_->end();
        }
        timer_->begin("view");
        Image image = renderViewCpu(setup, slotGrids,
                                    needLights ? lightVolumesCpu_ : std::vector<LightVolumeCpu>{},
                                    curved ? gradientCpu_ : std::vector<glm::vec4>{});
        timer_->end();
        if (lightsChanged) {
            lightInputs_ = std::move(lightInputs);
            ++lightVolumeUpdates_;
        }
        return image;
    }
    timer_->begin("upload");
    textures_->update(slotGrids);
    paramsBuffer_->upload(setup.params);
    timer_->end();
    if (gradientChanged) {
        refractionGpu_->compute(setup, *textures_, {}, timer_.get(), /*withOctree=*/false);
        gradientInputs_ = std::move(refractionInputs);
        ++gradientUpdates_;
    }
    if (lightsChanged) {
        lightVolumesGpu_->compute(setup, *textures_, timer_.get());
        lightInputs_ = std::move(lightInputs);
        ++lightVolumeUpdates_;
    }
    return viewPass_->render(setup, *textures_, *lightVolumesGpu_,
                             curved ? refractionGpu_->gradientTexture() : 0u, timer_.get());
}

}  // namespace eikon
