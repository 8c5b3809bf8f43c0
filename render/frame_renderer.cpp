#include "render/frame_renderer.h"

#include <cstdlib>

#include "core/camera.h"
#include "core/resample.h"
#include "render/environment_map.h"
#include "render/gl_context.h"
#include "render/input_key.h"
#include "render/params_buffer.h"
#include "render/photon_radiance.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"
#include "render/view_pass.h"
#include "render/volume_textures.h"
#include "render/voxelize.h"

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
    : scene_(scene), backend_(backend), sources_(scene_), meshFields_(scene_) {
    if (backend_ == Backend::Gpu) {
        if (!context) {
            ownContext_ = createHeadlessContext();
            context = ownContext_.get();
        }
        gl_ = context;
        textures_ = std::make_unique<VolumeTextures>();
        paramsBuffer_ = std::make_unique<ParamsBuffer>();
        hardwareTrilinear_ = useHardwareTrilinear(*gl_);
        // The CPU twin's rounding where it is cheap (software rasterizers): bit-identical photons.
        exactPhotonMath_ = isSoftwareRenderer(gl_->rendererName());
        lightVolumesGpu_ = std::make_unique<LightVolumesGpu>(hardwareTrilinear_);
        viewPass_ = std::make_unique<ViewPassGpu>(hardwareTrilinear_);
        refractionGpu_ = std::make_unique<RefractionVolumesGpu>();
        if (!scene_.meshes.empty()) voxelizerGpu_ = std::make_unique<MeshVoxelizerGpu>();
    }
    environment_ = std::make_unique<EnvironmentMap>(backend_ == Backend::Gpu);
    timer_ = std::make_unique<GpuStageTimer>(backend_ == Backend::Gpu);
}

FrameRenderer::~FrameRenderer() {
    // GL objects go before the context that owns them.
    timer_.reset();
    environment_.reset();
    viewPass_.reset();
    photonsGpu_.reset();
    voxelizerGpu_.reset();
    refractionGpu_.reset();
    lightVolumesGpu_.reset();
    paramsBuffer_.reset();
    textures_.reset();
    ownContext_.reset();
}

namespace {

void appendVersions(std::vector<unsigned char>& key, const std::vector<const DenseGrid*>& grids) {
    for (const DenseGrid* g : grids) appendBytes(key, &g->version, sizeof(g->version));
}

// The bytes the light volumes and the photon volumes depend on: the parameters without camera
// and image settings, and the versions of the field grids. Equal bytes, equal volumes.
std::vector<unsigned char> lightVolumeInputs(const ViewSetup& setup,
                                             const std::vector<const DenseGrid*>& grids) {
    shared::GpuViewParams p = setup.params;
    p.cameraOrigin = p.cameraRight = p.cameraUp = p.cameraForward = glm::vec4(0.0f);
    p.image.x = p.image.y = 0;
    p.background = glm::vec4(0.0f);
    p.environment = glm::ivec4(0);
    p.environmentSky = p.environmentHorizon = p.environmentGround = glm::vec4(0.0f);
    // Receivers stop photons but not the straight light of light volumes; their albedo only
    // shades the view.
    p.pipeline.w = 0;
    for (shared::GpuReceiver& r : p.receivers) r = shared::GpuReceiver{};
    std::vector<unsigned char> key;
    appendBytes(key, &p, sizeof(p));
    appendVersions(key, grids);
    return key;
}

// The photon volumes: the light volumes' inputs and the photon settings.
std::vector<unsigned char> photonInputs(const ViewSetup& setup,
                                        const std::vector<const DenseGrid*>& grids,
                                        const PhotonSettings& settings) {
    std::vector<unsigned char> key = lightVolumeInputs(setup, grids);
    for (int r = 0; r < setup.params.pipeline.w; ++r) {
        appendBytes(key, &setup.params.receivers[r].plane, sizeof(glm::vec4));
        appendBytes(key, &setup.params.receivers[r].texels, sizeof(glm::ivec4));
    }
    appendBytes(key, &settings.photonsPerSide, sizeof(settings.photonsPerSide));
    appendBytes(key, &settings.minStepVoxels, sizeof(settings.minStepVoxels));
    appendBytes(key, &settings.fluxThreshold, sizeof(settings.fluxThreshold));
    appendBytes(key, &settings.maxSteps, sizeof(settings.maxSteps));
    // The stop rule is checked once per round, so the round size changes what it cuts.
    appendBytes(key, &settings.stepsPerRound, sizeof(settings.stepsPerRound));
    appendBytes(key, &settings.stopFraction, sizeof(settings.stopFraction));
    appendBytes(key, &settings.seed, sizeof(settings.seed));
    appendBytes(key, &settings.frame, sizeof(settings.frame));
    return key;
}

// The bytes the ∇n volume (and the octree built on its n) depend on: the volume, the materials'
// index maps (ior − 1, 1/T_ambient) and field slots, and the versions of the field grids.
std::vector<unsigned char> gradientInputs(const ViewSetup& setup,
                                          const std::vector<const DenseGrid*>& grids) {
    const shared::GpuViewParams& p = setup.params;
    std::vector<float> values = {
        p.volumeMin.x,         p.volumeMin.y,        p.volumeMin.z,         p.volumeMax.x,
        p.volumeMax.y,         p.volumeMax.z,        float(p.resolution.x), float(p.resolution.y),
        float(p.resolution.z), float(p.resolution.w)};
    for (int m = 0; m < p.resolution.w; ++m) {
        values.push_back(p.materials[m].emission.w);
        values.push_back(p.materials[m].scattering.w);  // Gladstone–Dale's 1/T_ambient
        values.push_back(float(p.materials[m].slot.x));
    }
    std::vector<unsigned char> key;
    appendBytes(key, values.data(), values.size() * sizeof(float));
    appendVersions(key, grids);
    return key;
}

// The octree's: the ∇n volume's inputs, the octree settings, and, where extinction limits its
// steps, the materials' extinction (the field versions are in the ∇n inputs already).
std::vector<unsigned char> octreeInputs(const ViewSetup& setup,
                                        const std::vector<unsigned char>& gradientKey,
                                        const OctreeSettings& settings) {
    std::vector<unsigned char> key = gradientKey;
    appendBytes(key, &settings, sizeof(settings));
    if (settings.kappaTolerance > 0.0f)
        for (int m = 0; m < setup.params.resolution.w; ++m) {
            appendBytes(key, &setup.params.materials[m].absorption, sizeof(glm::vec4));
            appendBytes(key, &setup.params.materials[m].scattering, sizeof(glm::vec4));
        }
    return key;
}

}  // namespace

int FrameRenderer::environmentLoads() const {
    return environment_->loads();
}

void FrameRenderer::setMesh(size_t index, TriangleMesh objectSpace) {
    meshFields_.setMesh(scene_, index, std::move(objectSpace));
}

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
    environment_->update(scene_);
    timer_->end();

    volume_ = chooseRenderVolume(scene_, fields_, meshFields_.worldBounds(scene_));
    if (!scene_.meshes.empty()) {
        timer_->begin("voxelize");
        meshFields_.update(scene_, volume_, voxelizerGpu_.get(), dense_);
        timer_->end();
    }
    timer_->begin("resample");
    const CameraFrame camera =
        makeCameraFrame(scene_.camera, volume_.bounds, scene_.render.width, scene_.render.height);
    const Image& environment = environment_->image();
    const ViewSetup setup =
        makeViewSetup(scene_, volume_, camera, glm::ivec2(environment.width, environment.height));
    std::vector<const DenseGrid*> slotGrids;
    for (const std::string& name : setup.slotFields) {
        if (meshOfField(scene_, name) >= 0) {  // written by meshFields_ above
            slotGrids.push_back(&dense_.at(name));
            continue;
        }
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
    const bool photons = setup.params.pipeline.y != 0;
    // Photons march through the ∇n and octree volumes even where n ≡ 1 (their steps then grow
    // to the octree's limit).
    std::vector<unsigned char> refractionInputs;
    if (curved || photons) refractionInputs = gradientInputs(setup, slotGrids);
    const bool gradientChanged = (curved || photons) && refractionInputs != gradientInputs_;
    const OctreeSettings octreeSettings = octreeSettingsFor(scene_);
    std::vector<unsigned char> octreeKey;
    if (photons) octreeKey = octreeInputs(setup, refractionInputs, octreeSettings);
    const bool octreeChanged = photons && octreeKey != octreeInputs_;
    // n < 1 from a negative field is an input error, stopped before any stage uses it.
    if (gradientChanged || octreeChanged) checkRefractiveIndex(scene_, fields_, dense_);
    const PhotonSettings photonSettings = photonSettingsFor(scene_);
    std::vector<unsigned char> photonKey;
    if (photons) photonKey = photonInputs(setup, slotGrids, photonSettings);
    const bool photonsChanged = photons && photonKey != photonInputs_;

    if (backend_ == Backend::Cpu) {
        if (gradientChanged) {
            timer_->begin("gradient");
            gradientCpu_ = computeIndexGradientCpu(setup, slotGrids);
            timer_->end();
        }
        if (octreeChanged) {
            timer_->begin("octree");
            octreeCpu_ = computeOctreeCpu(setup, gradientCpu_, octreeSettings, slotGrids);
            timer_->end();
        }
        if (photonsChanged) {
            timer_->begin("photons");
            photonsCpu_ = computePhotonRadianceCpu(setup, slotGrids, gradientCpu_, octreeCpu_,
                                                   photonSettings);
            timer_->end();
            photonSteps_ += photonsCpu_.steps;
        }
        if (lightsChanged) {
            timer_->begin("light");
            lightVolumesCpu_ = computeLightVolumesCpu(setup, slotGrids);
            timer_->end();
        }
        timer_->begin("view");
        // Empty stand-ins by reference: `cond ? member : {}` would copy the member every frame.
        static const std::vector<LightVolumeCpu> noLightVolumes;
        static const std::vector<glm::vec4> noGradient;
        Image image = renderViewCpu(
            setup, slotGrids, needLights ? lightVolumesCpu_ : noLightVolumes,
            curved ? gradientCpu_ : noGradient, photons ? &photonsCpu_ : nullptr, &environment);
        timer_->end();
        commitInputs(gradientChanged, octreeChanged, photonsChanged, lightsChanged,
                     std::move(refractionInputs), std::move(octreeKey), std::move(photonKey),
                     std::move(lightInputs));
        return image;
    }
    timer_->begin("upload");
    textures_->update(slotGrids);
    paramsBuffer_->upload(setup.params);
    timer_->end();
    if (gradientChanged || octreeChanged)
        refractionGpu_->compute(setup, *textures_, octreeSettings, timer_.get(),
                                /*withOctree=*/photons);
    if (photonsChanged) {
        if (!photonsGpu_) photonsGpu_ = std::make_unique<PhotonRadianceGpu>(exactPhotonMath_);
        photonsGpu_->compute(setup, *textures_, *refractionGpu_, photonSettings, timer_.get());
        photonSteps_ += photonsGpu_->lastSteps();
    }
    if (lightsChanged) lightVolumesGpu_->compute(setup, *textures_, timer_.get());
    commitInputs(gradientChanged, octreeChanged, photonsChanged, lightsChanged,
                 std::move(refractionInputs), std::move(octreeKey), std::move(photonKey),
                 std::move(lightInputs));
    return viewPass_->render(
        setup, *textures_, *lightVolumesGpu_, curved ? refractionGpu_->gradientTexture() : 0u,
        photons ? photonsGpu_.get() : nullptr, timer_.get(), environment_->texture());
}

void FrameRenderer::commitInputs(bool gradientChanged, bool octreeChanged, bool photonsChanged,
                                 bool lightsChanged, std::vector<unsigned char> refractionInputs,
                                 std::vector<unsigned char> octreeKey,
                                 std::vector<unsigned char> photonKey,
                                 std::vector<unsigned char> lightInputs) {
    if (octreeChanged) octreeInputs_ = std::move(octreeKey);
    if (gradientChanged) {
        gradientInputs_ = std::move(refractionInputs);
        ++gradientUpdates_;
    }
    if (photonsChanged) {
        photonInputs_ = std::move(photonKey);
        ++photonUpdates_;
    }
    if (lightsChanged) {
        lightInputs_ = std::move(lightInputs);
        ++lightVolumeUpdates_;
    }
}

int64_t FrameRenderer::lastPhotonsTraced() const {
    if (backend_ == Backend::Gpu) return photonsGpu_ ? photonsGpu_->lastPhotonsTraced() : 0;
    return photonsCpu_.photonsTraced;
}

int64_t FrameRenderer::lastPhotonsCut() const {
    if (backend_ == Backend::Gpu) return photonsGpu_ ? photonsGpu_->lastPhotonsCut() : 0;
    return photonsCpu_.photonsCut;
}

int FrameRenderer::lastPhotonRounds() const {
    if (backend_ == Backend::Gpu) return photonsGpu_ ? photonsGpu_->lastRounds() : 0;
    return photonsCpu_.rounds;
}

PhotonRadianceCpu FrameRenderer::photonVolumes() const {
    if (backend_ == Backend::Gpu)
        return photonsGpu_ ? photonsGpu_->download() : PhotonRadianceCpu{};
    return photonsCpu_;
}

}  // namespace eikon
