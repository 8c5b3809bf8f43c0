#include "render/frame_renderer.h"

#include <cstdlib>

#include "core/camera.h"
#include "core/resample.h"
#include "core/transfer_function.h"
#include "render/constant_bricks.h"
#include "render/environment_map.h"
#include "render/gl_context.h"
#include "render/input_key.h"
#include "render/light_transport_registry.h"
#include "render/params_buffer.h"
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

// How the CPU twin's view runs, each choice to the same bits: it steps through empty space
// without sampling it (render/empty_bricks.h; EIKON_SKIP_EMPTY_SPACE=0 takes every step in full)
// runs its AVX2 copy where the processor has one (EIKON_CPU_AVX2=0 runs the baseline x86-64
// copy), its AVX-512 copy where it has that too (EIKON_CPU_AVX512=0 runs the AVX2 copy) and takes
// samples in constant bricks without fetching their corners (render/constant_bricks.h;
// EIKON_CONSTANT_BRICKS=0 fetches them), the switches there to measure what each gains.
ViewCpuOptions viewCpuOptions() {
    const auto off = [](const char* name) {
        const char* env = std::getenv(name);
        return env && std::string(env) == "0";
    };
    ViewCpuOptions options;
    options.skipEmptySpace = !off("EIKON_SKIP_EMPTY_SPACE");
    options.avx2 = !off("EIKON_CPU_AVX2");
    options.avx512 = !off("EIKON_CPU_AVX512");
    options.constantBricks = constantBricksEnabled();
    return options;
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
        device_.gpu = true;
        device_.hardwareTrilinear = hardwareTrilinear_;
        // The CPU twin's rounding where it is cheap (software rasterizers): bit-identical photons.
        device_.exactMath = isSoftwareRenderer(gl_->rendererName());
        viewPass_ = std::make_unique<ViewPassGpu>(hardwareTrilinear_);
        refractionGpu_ = std::make_unique<RefractionVolumesGpu>();
        if (!scene_.meshes.empty()) voxelizerGpu_ = std::make_unique<MeshVoxelizerGpu>();
    }
    // A bad method or setting fails here, before any frame is rendered.
    transport_ = makeLightTransport(scene_, device_);
    transportSection_ = scene_.render.lightTransport;
    environment_ = std::make_unique<EnvironmentMap>(backend_ == Backend::Gpu);
    timer_ = std::make_unique<GpuStageTimer>(backend_ == Backend::Gpu);
}

FrameRenderer::~FrameRenderer() {
    // GL objects go before the context that owns them.
    timer_.reset();
    environment_.reset();
    viewPass_.reset();
    transport_.reset();
    voxelizerGpu_.reset();
    refractionGpu_.reset();
    paramsBuffer_.reset();
    textures_.reset();
    ownContext_.reset();
}

namespace {

// The bytes the ∇n volume (and the octree built on its n) depend on: the volume, the materials'
// index maps (ior − 1, 1/T_ambient) and field slots, and the versions of the field grids.
std::vector<unsigned char> gradientInputs(const ViewSetup& setup,
                                          const std::vector<const DenseGrid*>& grids) {
    const shared::GpuViewParams& p = setup.params;
    const int materials = shared::materialCount(p);
    std::vector<float> values = {
        p.volumeMin.x,         p.volumeMin.y,   p.volumeMin.z,         p.volumeMax.x,
        p.volumeMax.y,         p.volumeMax.z,   float(p.resolution.x), float(p.resolution.y),
        float(p.resolution.z), float(materials)};
    for (int m = 0; m < materials; ++m) {
        values.push_back(shared::materialIndexSlope(p.materials[m]));
        values.push_back(shared::materialInverseAmbient(p.materials[m]));
        values.push_back(float(shared::materialSlot(p.materials[m])));
    }
    // Dispersion's channel volumes are computed with the gradient (FrameRenderer::render).
    for (const glm::vec3& slopes : setup.channelIndexSlopes)
        values.insert(values.end(), {slopes.x, slopes.y, slopes.z});
    std::vector<unsigned char> key;
    appendBytes(key, values.data(), values.size() * sizeof(float));
    for (const DenseGrid* g : grids) appendBytes(key, &g->version, sizeof(g->version));
    return key;
}

// The octree's: the ∇n volume's inputs, the octree settings, and, where extinction limits its
// steps, the materials' extinction and what clips it (the field versions are in the ∇n inputs
// already).
std::vector<unsigned char> octreeInputs(const ViewSetup& setup,
                                        const std::vector<unsigned char>& gradientKey,
                                        const OctreeSettings& settings) {
    std::vector<unsigned char> key = gradientKey;
    appendBytes(key, &settings, sizeof(settings));
    if (settings.kappaTolerance > 0.0f)
        for (int m = 0; m < shared::materialCount(setup.params); ++m) {
            // κ's inputs only: not g (absorption.w), n's (scattering.w, in the gradient's key),
            // the sharp surfaces or the particle colour's slot (slot.y, slot.w), which a
            // viewer's edit of a phase function or a colour map would otherwise rebuild it for.
            const shared::GpuMaterial& mat = setup.params.materials[m];
            const glm::vec3 absorption(mat.absorption), scattering(mat.scattering);
            const glm::ivec2 slotAndClips(mat.slot.x, mat.slot.z);
            appendBytes(key, &absorption, sizeof(absorption));
            appendBytes(key, &scattering, sizeof(scattering));
            appendBytes(key, &slotAndClips, sizeof(slotAndClips));
        }
    if (settings.kappaTolerance > 0.0f)
        appendBytes(key, setup.params.clipPlanes, sizeof(setup.params.clipPlanes));
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

void FrameRenderer::setStageListener(std::function<void(const std::string&)> listener) {
    timer_->setListener(std::move(listener));
}

std::vector<StageTime> FrameRenderer::takeStats() {
    std::vector<StageTime> out = timer_->results();
    timer_->reset();
    return out;
}

Image FrameRenderer::render(const FrameInputs& inputs) {
    scene_ = inputs.scene;
    for (const auto& [index, mesh] : inputs.meshes) setMesh(index, mesh);
    for (const std::string& name : inputs.fields.names()) {
        const Field& field = inputs.fields.get(name);
        fields_.set(name, field.grid, field.origin);
    }
    return render(inputs.frame);
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
    const ViewSetup setupWithoutTransport =
        makeViewSetup(scene_, volume_, camera, glm::ivec2(environment.width, environment.height));
    std::vector<const DenseGrid*> slotGrids;
    for (const std::string& name : setupWithoutTransport.slotFields) {
        const MaterialSpec* classified = transferMaterialOfSlot(scene_, name);
        const std::string fieldName = classified ? classified->field : name;
        const DenseGrid* grid = nullptr;
        if (meshOfField(scene_, fieldName) >= 0) {  // written by meshFields_ above
            grid = &dense_.at(fieldName);
        } else {
            const Field& f = fields_.get(fieldName);
            auto it = dense_.find(fieldName);
            if (it == dense_.end() || it->second.version != f.version ||
                it->second.volume != volume_) {
                dense_[fieldName] = resampleToDense(f, volume_);
                ++resamples_;
            }
            grid = &dense_[fieldName];
        }
        if (classified) grid = &classifiedSlot(name, *grid, classified->transfer);
        slotGrids.push_back(grid);
    }
    timer_->end();

    updateTransport(setupWithoutTransport, slotGrids);
    ViewSetup setup = setupWithoutTransport;
    transport_->configure(scene_, setup);
    std::vector<unsigned char> transportKey = transport_->cacheKey(setup, slotGrids);
    const bool transportActive = !transportKey.empty();
    bool transportChanged = transportActive && transportKey != transportInputs_;
    // A preview whose light must be traced again traces it lighter; `used` is what the view reads.
    LightTransport* used = transport_.get();
    std::vector<unsigned char> previewKey;
    bool previewChanged = false;
    if (preview_ && transportChanged) {
        if (LightTransport* lighter = previewTransport()) {
            ViewSetup previewSetup = setupWithoutTransport;
            lighter->configure(scene_, previewSetup);
            previewKey = lighter->cacheKey(previewSetup, slotGrids);
            if (!previewKey.empty()) {
                setup = std::move(previewSetup);
                used = lighter;
                transportChanged = false;
                previewChanged = previewKey != previewInputs_;
            }
        }
    }
    const TransportNeeds needs = used->needs();
    // A method that views as it lights (the plane sweep's interleaved view) runs every frame, in
    // the view stage, whatever changed: its image depends on the camera too.
    const bool interleaved = transportActive && used->viewsInterleaved();
    const bool runTransport = (transportChanged || previewChanged) && !interleaved;
    const bool curved = shared::curvedRays(setup.params);
    // The octree is built on the ∇n volume's n: a method that needs it needs that volume too.
    const bool wantGradient = curved || (transportActive && (needs.gradient || needs.octree));
    const bool wantOctree = transportActive && needs.octree;
    // Dispersion: view rays of each colour channel bend with its own n, through its ∇n volume.
    const bool disperses = curved && dispersesView(setup);
    std::vector<unsigned char> refractionInputs;
    if (wantGradient) refractionInputs = gradientInputs(setup, slotGrids);
    const bool gradientChanged = wantGradient && refractionInputs != gradientInputs_;
    std::vector<unsigned char> octreeKey;
    if (wantOctree) octreeKey = octreeInputs(setup, refractionInputs, needs.octreeSettings);
    const bool octreeChanged = wantOctree && octreeKey != octreeInputs_;
    // n < 1 from a negative field is an input error, stopped before any stage uses it.
    if (gradientChanged || octreeChanged) checkRefractiveIndex(scene_, fields_, dense_);

    if (backend_ == Backend::Cpu) {
        if (gradientChanged) {
            timer_->begin("gradient");
            gradientCpu_ = computeIndexGradientCpu(setup, slotGrids);
            timer_->end();
        }
        if (disperses && (gradientChanged || channelGradientsCpu_.red.empty())) {
            timer_->begin("gradient");
            channelGradientsCpu_ = computeChannelGradientsCpu(setup, slotGrids);
            timer_->end();
        } else if (!disperses) {
            channelGradientsCpu_ = {};  // free what a dispersive scene before needed
        }
        if (octreeChanged) {
            timer_->begin("octree");
            octreeCpu_ = computeOctreeCpu(setup, gradientCpu_, needs.octreeSettings, slotGrids);
            timer_->end();
        }
        if (runTransport)
            used->runCpu({setup, slotGrids, gradientCpu_, octreeCpu_, timer_.get(),
                          disperses ? &channelGradientsCpu_ : nullptr});
    } else {
        timer_->begin("upload");
        textures_->update(slotGrids);
        paramsBuffer_->upload(setup.params);
        timer_->end();
        if (gradientChanged || octreeChanged)
            refractionGpu_->compute(setup, *textures_, needs.octreeSettings, timer_.get(),
                                    wantOctree);
        if (disperses && (gradientChanged || !refractionGpu_->channelGradientTexture(0)))
            refractionGpu_->computeChannelGradients(setup, *textures_, *paramsBuffer_,
                                                    timer_.get());
        if (runTransport)
            used->runGpu({setup, *textures_, *refractionGpu_, timer_.get(), disperses});
    }
    if (runTransport) {
        lastTransportStats_ = used->stats();
        transportSteps_ += lastTransportStats_.steps;
    }
    if (transportChanged) {
        if (!interleaved) ++transportRuns_[transport_->name()];  // counted where it runs, below
        transportInputs_ = std::move(transportKey);
    }
    if (previewChanged) {
        ++previewRuns_;
        previewInputs_ = std::move(previewKey);
    }
    if (octreeChanged) {
        octreeInputs_ = std::move(octreeKey);
        ++octreeUpdates_;
    }
    if (gradientChanged) {
        gradientInputs_ = std::move(refractionInputs);
        ++gradientUpdates_;
    }

    if (backend_ == Backend::Cpu && interleaved) {  // it times its stages, the view's included
        Image image =
            used->runWithViewCpu({setup, slotGrids, gradientCpu_, octreeCpu_, timer_.get(),
                                  disperses ? &channelGradientsCpu_ : nullptr},
                                 &environment);
        lastTransportStats_ = used->stats();
        transportSteps_ += lastTransportStats_.steps;
        ++transportRuns_[used->name()];
        return image;
    }
    if (interleaved) {  // GPU: as on the CPU twin above
        Image image = used->runWithViewGpu(
            {setup, *textures_, *refractionGpu_, timer_.get(), disperses}, environment_->texture());
        lastTransportStats_ = used->stats();
        transportSteps_ += lastTransportStats_.steps;
        ++transportRuns_[used->name()];
        return image;
    }
    if (backend_ == Backend::Cpu) {
        timer_->begin("view");
        // Empty stand-ins by reference: `cond ? member : {}` would copy the member every frame.
        static const std::vector<glm::vec4> noGradient;
        Image image = renderViewCpu(setup, slotGrids,
                                    transportActive ? used->outputCpu() : TransportOutputCpu{},
                                    curved ? gradientCpu_ : noGradient, &environment,
                                    disperses ? &channelGradientsCpu_ : nullptr, viewCpuOptions());
        timer_->end();
        return image;
    }
    ViewDispersionGpu dispersion;
    if (disperses) {
        for (int c = 0; c < 3; ++c)
            dispersion.gradientTextures[c] = refractionGpu_->channelGradientTexture(c);
        dispersion.params = paramsBuffer_.get();
    }
    return viewPass_->render(setup, *textures_, transportActive ? used : nullptr,
                             curved ? refractionGpu_->gradientTexture() : 0u, timer_.get(),
                             environment_->texture(), disperses ? &dispersion : nullptr);
}

// The method in use keeps its output and its GPU resources while the scene asks for the same
// method with the same settings. Another method ("auto" picks another when the materials or the
// receivers change) takes over at once; new settings of the same method take over when they
// change what its output depends on (its cache key), not when they only touch another method's
// section.
// The slot of a material with a transfer function: its field's dense grid mapped through it,
// again only when the field's grid or the function changed. Its version is one of its own, new
// each time, so the upload and the caches keyed on versions see the change.
const DenseGrid& FrameRenderer::classifiedSlot(const std::string& slotName, const DenseGrid& field,
                                               const std::vector<glm::vec2>& transfer) {
    Classified& c = classified_[slotName];
    auto it = dense_.find(slotName);
    if (it == dense_.end() || c.fieldVersion != field.version || c.volume != field.volume ||
        c.transfer != transfer) {
        c = Classified{field.version, field.volume, transfer};
        dense_[slotName] = applyTransfer(field, transfer, slotName, nextClassifiedVersion_++);
    }
    return dense_.at(slotName);
}

void FrameRenderer::updateTransport(const ViewSetup& base,
                                    const std::vector<const DenseGrid*>& slotGrids) {
    std::unique_ptr<LightTransport> fresh = makeLightTransport(scene_, device_);
    bool adopt = fresh->name() != transport_->name();
    if (!adopt && scene_.render.lightTransport != transportSection_) {
        ViewSetup setup = base;
        fresh->configure(scene_, setup);
        adopt = transportInputs_.empty() || fresh->cacheKey(setup, slotGrids) != transportInputs_;
    }
    transportSection_ = scene_.render.lightTransport;
    if (!adopt) return;
    transport_ = std::move(fresh);
    transportInputs_.clear();
}

LightTransport* FrameRenderer::previewTransport() {
    const std::string patch = transport_->previewPatch();
    if (patch.empty()) {
        previewTransport_.reset();
        return nullptr;
    }
    Scene lighter = scene_;
    patchLightTransport(lighter, patch);
    if (!previewTransport_ || previewTransport_->name() != transport_->name() ||
        lighter.render.lightTransport != previewSection_) {
        previewTransport_ = makeLightTransport(lighter, device_);
        previewSection_ = lighter.render.lightTransport;
        previewInputs_.clear();
    }
    return previewTransport_.get();
}

int FrameRenderer::transportRuns(const std::string& method) const {
    auto it = transportRuns_.find(method);
    return it == transportRuns_.end() ? 0 : it->second;
}

}  // namespace eikon
