// Refraction volumes, stages 2 and 3 of Sun et al. 2008: n and ∇n against closed forms, the
// octree's labels and step limits on fields whose pyramid is known by hand, and the GPU against
// the CPU twin on a volume whose sides are not powers of two.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>

#include "core/camera.h"
#include "render/gl_context.h"
#include "render/params_buffer.h"
#include "render/refraction_volume.h"
#include "render/volume_kernels_cpu.h"
#include "render/volume_textures.h"
#include "shaders/shared/material_index.h"  // at file scope: refraction.h calls it

EK_NAMESPACE_BEGIN
// The shared refraction functions on the CPU, as render/refraction_volume_cpu.cpp compiles them.
struct RefractionTestKernel : VolumeAccessCpu {
#include "shaders/shared/refraction.h"
};
EK_NAMESPACE_END

using namespace eikon;

namespace {

constexpr float kIor = 1.5f;

// One material of index kIor whose field is given per voxel (index and centre), built directly
// as a DenseGrid so that every value is known exactly; optionally a second material of index
// hazeIor on a second field, 1 − the first, so that materials add.
struct IndexScene {
    Scene scene;
    RenderVolume volume;
    DenseGrid density;
    DenseGrid haze;
    ViewSetup setup;

    IndexScene(glm::ivec3 resolution, const Bounds3& bounds,
               const std::function<float(glm::ivec3, glm::vec3)>& field, float hazeIor = 0.0f) {
        MaterialSpec m;
        m.name = "glass";
        m.ior = kIor;
        scene.materials.push_back(m);
        if (hazeIor > 0.0f) {
            m.name = m.field = "haze";
            m.ior = hazeIor;
            scene.materials.push_back(m);
        }
        scene.render.width = scene.render.height = 8;
        volume.bounds = bounds;
        volume.resolution = resolution;
        density.field = "density";
        density.volume = volume;
        density.values.resize(volume.voxelCount());
        for (int k = 0; k < resolution.z; ++k)
            for (int j = 0; j < resolution.y; ++j)
                for (int i = 0; i < resolution.x; ++i)
                    density.values[density.index(i, j, k)] =
                        field(glm::ivec3(i, j, k), volume.voxelCenter(i, j, k));
        haze = density;
        haze.field = "haze";
        for (float& v : haze.values) v = 1.0f - v;
        setup = makeViewSetup(scene, volume, makeCameraFrame(scene.camera, volume.bounds, 8, 8));
    }

    std::vector<const DenseGrid*> slotGrids() const {
        if (setup.slotFields.size() == 1) return {&density};
        return {&density, &haze};
    }
    RefractionVolumeCpu gradient() const { return computeIndexGradientCpu(setup, slotGrids()); }
    RefractionVolumeCpu octree(const OctreeSettings& settings = {}) const {
        return computeOctreeCpu(setup, gradient(), settings);
    }
};

const Bounds3 kCube{glm::vec3(-1.0f), glm::vec3(1.0f)};

// A ball of radius 0.5 around `centre` whose field falls from 1 to 0 over ~0.1 across its rim.
float ballField(glm::vec3 x, glm::vec3 centre) {
    return 0.5f * (1.0f - std::tanh((glm::length(x - centre) - 0.5f) / 0.1f));
}

float maxAbsDifference(const RefractionVolumeCpu& a, const RefractionVolumeCpu& b, int channel) {
    float worst = 0.0f;
    for (size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(a[i][channel] - b[i][channel]));
    return worst;
}

}  // namespace

TEST_CASE("gradient of a linear field equals the analytic one everywhere", "[refraction]") {
    // Anisotropic voxels (0.125 x 0.0833 x 0.3): each axis must divide by its own voxel size.
    const Bounds3 box{glm::vec3(-1.0f, -0.5f, 0.0f), glm::vec3(1.0f, 0.5f, 3.0f)};
    const glm::vec3 slope(0.2f, 0.3f, -0.1f);  // field per scene unit
    auto linear = [&](glm::ivec3, glm::vec3 x) {
        return 0.5f + glm::dot(slope, x - glm::vec3(0.0f, 0.0f, 1.5f));
    };
    // Two materials, f of index 1.5 and 1 − f of index 1.2: n = 1 + 0.5 f + 0.2 (1 − f).
    const IndexScene s(glm::ivec3(16, 12, 10), box, linear, 1.2f);
    const RefractionVolumeCpu g = s.gradient();
    const glm::vec3 exact = slope * 0.3f;
    double worstGradient = 0.0, worstIndex = 0.0;
    for (int k = 0; k < 10; ++k)
        for (int j = 0; j < 12; ++j)
            for (int i = 0; i < 16; ++i) {
                const glm::vec4 v = g[s.density.index(i, j, k)];
                // One-sided differences at the faces are exact for a linear field too.
                worstGradient = std::max(
                    worstGradient, double(glm::length(glm::vec3(v) - exact) / glm::length(exact)));
                const float f = s.density.at(i, j, k);
                const double n = 1.0 + 0.5 * double(f) + 0.2 * (1.0 - double(f));
                worstIndex = std::max(worstIndex, std::abs(double(v.w) - n));
            }
    INFO("max relative gradient error " << worstGradient << ", max |n error| " << worstIndex);
    CHECK(worstGradient < 1e-4);
    CHECK(worstIndex < 1e-6);

    // Between the centres, the trilinear n the photon march will read is linear too.
    shared::RefractionTestKernel kernel{{s.setup.params}};
    kernel.fields[0] = s.density.values.data();
    kernel.fields[1] = s.haze.values.data();
    double worstTrilinear = 0.0;
    for (glm::vec3 p : {glm::vec3(0.7f, 0.6f, 0.9f), glm::vec3(7.3f, 5.55f, 4.01f),
                        glm::vec3(15.2f, 11.4f, 9.3f)}) {
        const glm::vec3 world = s.volume.bounds.min + p * s.volume.voxelSize();
        const double n = 1.2 + 0.3 * double(linear(glm::ivec3(0), world));
        worstTrilinear =
            std::max(worstTrilinear, std::abs(double(kernel.refractiveIndexAt(p)) - n));
    }
    INFO("max |trilinear n error| " << worstTrilinear);
    CHECK(worstTrilinear < 1e-6);
}

TEST_CASE("gradient of a soft ball points toward its centre", "[refraction]") {
    const glm::vec3 centre(0.1f, -0.05f, 0.03f);  // off the voxel grid
    const IndexScene s(glm::ivec3(32), kCube,
                       [&](glm::ivec3, glm::vec3 x) { return ballField(x, centre); });
    const RefractionVolumeCpu g = s.gradient();
    float strongest = 0.0f;
    for (const glm::vec4& v : g) strongest = std::max(strongest, glm::length(glm::vec3(v)));
    double worstAngle = 0.0;
    int checked = 0;
    for (int k = 0; k < 32; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 32; ++i) {
                const glm::vec3 grad(g[s.density.index(i, j, k)]);
                if (glm::length(grad) < 0.1f * strongest) continue;
                const glm::vec3 inward = glm::normalize(centre - s.volume.voxelCenter(i, j, k));
                const double c = glm::dot(glm::normalize(grad), inward);
                worstAngle = std::max(worstAngle, std::acos(std::min(c, 1.0)) * 180.0 / M_PI);
                ++checked;
            }
    INFO("max |grad n| " << strongest << ", voxels checked " << checked << ", worst angle "
                         << worstAngle << " degrees");
    CHECK(checked > 1000);
    CHECK(worstAngle < 5.0);
}

TEST_CASE("octree labels: flat, a step and a gentle ramp", "[refraction]") {
    const OctreeSettings settings;
    SECTION("constant n: the single coarsest node, unlimited steps") {
        const IndexScene s(glm::ivec3(20, 17, 13), kCube,
                           [](glm::ivec3, glm::vec3) { return 0.3f; });
        REQUIRE(octreeLevelCount(glm::ivec3(20, 17, 13)) == 6);  // 32 covers 20
        for (const glm::vec4& o : s.octree(settings)) {
            CHECK(o.x == 5.0f);
            CHECK(o.y == kUnlimitedStep);
            CHECK(o.z == o.w);
        }
    }
    SECTION("a step in n between voxels 10 and 11 along x") {
        // Level-0 ranges reach two voxels around each voxel (octree.h), so voxels 9..12 see the
        // step. Level-k nodes span [m·2^k, (m+1)·2^k): those overlapping 9..12 are not flat, so
        // voxels 8..13 find no node of level ≥ 1 within ε' (label 0, the minimum step); 14 and 15
        // take the level-1 node beside them, the rest the coarsest node clear of 9..12.
        const IndexScene s(glm::ivec3(32), kCube,
                           [](glm::ivec3 v, glm::vec3) { return v.x >= 11 ? 1.0f : 0.0f; });
        const RefractionVolumeCpu o = s.octree(settings);
        const float minStep = 2.0f / 32.0f;
        auto expectedLevel = [](int x) {
            if (x < 8) return 3;
            if (x < 14) return 0;
            if (x < 16) return 1;
            return 4;
        };
        for (int k = 0; k < 32; ++k)
            for (int j = 0; j < 32; ++j)
                for (int i = 0; i < 32; ++i) {
                    const glm::vec4 v = o[s.density.index(i, j, k)];
                    INFO("voxel x " << i);
                    REQUIRE(v.x == float(expectedLevel(i)));
                    REQUIRE(v.y == (expectedLevel(i) == 0 ? minStep : kUnlimitedStep));
                }
    }
    SECTION("a ramp of 0.0015 per voxel: capped steps at the 8-voxel nodes") {
        // n = 1 + 0.5 f. A level-k node with its two-voxel rim spans 2^k + 4 voxels: ranges
        // 0.0075 (level 1), 0.0105 (2), 0.0165 (3), 0.0285 (4); at the faces the rim is cut, so
        // less. Walking down from the top, level 3 is the first within ε' = 0.02 but not within
        // ε = 0.005: label 3, steps capped at 8 voxels.
        const IndexScene s(glm::ivec3(32), kCube,
                           [](glm::ivec3 v, glm::vec3) { return 0.003f * float(v.x); });
        const float limit = 8.0f * 2.0f / 32.0f;
        for (const glm::vec4& v : s.octree(settings)) {
            REQUIRE(v.x == 3.0f);
            REQUIRE(v.y == limit);
            REQUIRE(v.w - v.z <= Approx(0.0165f).margin(1e-6));
            REQUIRE(v.w - v.z >= Approx(0.0135f).margin(1e-6));
        }
    }
}

TEST_CASE("GPU gradient and octree equal the CPU twins", "[refraction][gpu]") {
    auto context = createHeadlessContext();
    const glm::ivec3 res(20, 17, 13);
    const Bounds3 box{glm::vec3(-1.0f, -0.9f, -0.7f), glm::vec3(1.0f, 0.8f, 0.6f)};
    const IndexScene s(
        res, box,
        [](glm::ivec3, glm::vec3 x) { return ballField(x, glm::vec3(0.1f, -0.05f, 0.03f)); }, 1.2f);
    REQUIRE(s.setup.slotFields.size() == 2);
    const RefractionVolumeCpu cpuGradient = s.gradient();
    const RefractionVolumeCpu cpuOctree = s.octree();
    VolumeTextures textures;
    textures.update(s.slotGrids());
    ParamsBuffer params;
    params.upload(s.setup.params);
    // The gradient pass fetches voxel values only (no trilinear sampling path to vary), and the
    // pyramid and labels are min, max and compares: both stages match the CPU bit for bit on
    // llvmpipe; the bounds leave room for drivers whose division is not correctly rounded.
    RefractionVolumesGpu gpu;
    gpu.compute(s.setup, textures);
    const RefractionVolumeCpu gradient = gpu.downloadGradient();
    const RefractionVolumeCpu octree = gpu.downloadOctree();
    REQUIRE(gradient.size() == cpuGradient.size());
    float gradientDiff = 0.0f, strongest = 0.0f;
    for (int c = 0; c < 3; ++c)
        gradientDiff = std::max(gradientDiff, maxAbsDifference(gradient, cpuGradient, c));
    for (const glm::vec4& v : cpuGradient)
        strongest = std::max(strongest, glm::length(glm::vec3(v)));
    const float indexDiff = maxAbsDifference(gradient, cpuGradient, 3);
    INFO("max |GPU - CPU|: grad n " << gradientDiff << " (max |grad n| " << strongest << "), n "
                                    << indexDiff);
    CHECK(gradientDiff <= 1e-6f * strongest);
    CHECK(indexDiff <= 1e-6f);
    // The octree from the GPU's own n; labels and steps must agree exactly.
    int labelMismatches = 0;
    for (size_t i = 0; i < octree.size(); ++i)
        if (octree[i].x != cpuOctree[i].x || octree[i].y != cpuOctree[i].y) ++labelMismatches;
    CHECK(labelMismatches == 0);
    CHECK(maxAbsDifference(octree, cpuOctree, 2) <= 1e-6f);
    CHECK(maxAbsDifference(octree, cpuOctree, 3) <= 1e-6f);
    // And the volume is not trivial: the ball's rim gets label 0, the corners coarse labels.
    float finest = 99.0f, coarsest = 0.0f;
    for (const glm::vec4& o : octree) {
        finest = std::min(finest, o.x);
        coarsest = std::max(coarsest, o.x);
    }
    CHECK(finest == 0.0f);
    CHECK(coarsest >= 2.0f);
}

namespace {

// One Gladstone–Dale material reading a row of temperature excesses, one per voxel along x.
struct HotAirRow {
    Scene scene;
    RenderVolume volume;
    DenseGrid temperature;
    ViewSetup setup;

    HotAirRow(const std::vector<float>& excess, float gladstoneDale, float ambientKelvin) {
        MaterialSpec m;
        m.name = "hot_air";
        m.field = "temperature";
        m.gladstoneDale = gladstoneDale;
        m.ambientKelvin = ambientKelvin;
        m.ior = 1.0f - gladstoneDale / ambientKelvin;  // as the parser sets it
        scene.materials.push_back(m);
        scene.render.width = scene.render.height = 8;
        volume.bounds = Bounds3{glm::vec3(0.0f), glm::vec3(float(excess.size()), 1.0f, 1.0f)};
        volume.resolution = glm::ivec3(int(excess.size()), 1, 1);
        temperature.field = "temperature";
        temperature.volume = volume;
        temperature.values = excess;
        setup = makeViewSetup(scene, volume, makeCameraFrame(scene.camera, volume.bounds, 8, 8));
    }
};

// Gladstone–Dale relative to ambient air: n − 1 of air is GD·T_amb/T, so
// n = 1 + GD·(T_amb/(T_amb + f) − 1), in double.
double hotAirIndex(double f, double gladstoneDale, double ambientKelvin) {
    return 1.0 + gladstoneDale * (ambientKelvin / (ambientKelvin + f) - 1.0);
}

const std::vector<float> kExcessKelvin = {-150.0f, -20.0f, 0.0f, 5.0f, 30.0f, 288.15f, 1500.0f};

}  // namespace

TEST_CASE("Gladstone-Dale hot air: n follows the exact 1/T law per voxel, far from ambient too",
          "[refraction][gladstone-dale]") {
    constexpr float kAmbient = 288.15f;
    // An exaggerated constant (what scenes use to see the effect) and real air's.
    for (float gd : {0.5f, 2.9e-4f}) {
        const HotAirRow row(kExcessKelvin, gd, kAmbient);
        const RefractionVolumeCpu g = computeIndexGradientCpu(row.setup, {&row.temperature});
        for (size_t v = 0; v < kExcessKelvin.size(); ++v) {
            const double f = kExcessKelvin[v];
            const double exact = hotAirIndex(f, gd, kAmbient);
            const double linear = 1.0 - f * gd / kAmbient;  // the old linearisation
            INFO("GD " << gd << ", T - T_ambient = " << f << " K: n " << g[v].w << ", exact "
                       << exact << ", linearised " << linear);
            // Relative to n − 1 of the ambient air, so that real air's 1e-4 is held to float
            // precision of the excess, not of n: |Δn| ≤ 1e-3·GD ≪ the linearisation's f/T_amb.
            CHECK(std::abs(double(g[v].w) - exact) <= 1e-3 * gd + 1e-7);
            if (std::abs(f) >= 150.0) CHECK(std::abs(linear - exact) > 0.3 * gd);
        }
    }
}

TEST_CASE("Gladstone-Dale hot air: the GPU's n equals the CPU twin's", "[refraction][gpu]") {
    auto context = createHeadlessContext();
    const HotAirRow row(kExcessKelvin, 0.5f, 288.15f);
    const RefractionVolumeCpu cpu = computeIndexGradientCpu(row.setup, {&row.temperature});
    VolumeTextures textures;
    textures.update({&row.temperature});
    ParamsBuffer params;
    params.upload(row.setup.params);
    RefractionVolumesGpu gpu;
    gpu.compute(row.setup, textures);
    const RefractionVolumeCpu gradient = gpu.downloadGradient();
    REQUIRE(gradient.size() == cpu.size());
    // One division per voxel: correctly rounded on llvmpipe; 1e-6 leaves room for drivers whose
    // division is not.
    CHECK(maxAbsDifference(gradient, cpu, 3) <= 1e-6f);
}

// The twin's leaf ranges come from separable min/max passes (refraction_volume.h); the shared
// pyramidLeafRange, voxel by voxel, is the oracle: the same floats everywhere, faces included,
// on a noisy two-material field with extinction and a clip plane on one material (whose κ bounds
// differ from κ at the centre), and on volumes thinner than the windows.
TEST_CASE("octree leaf ranges: separable passes equal the shared per-voxel ranges bit for bit",
          "[refraction][octree]") {
    auto noise = [](glm::ivec3 v, glm::vec3) {
        const uint32_t h =
            (uint32_t(v.x) * 73856093u) ^ (uint32_t(v.y) * 19349663u) ^ (uint32_t(v.z) * 83492791u);
        return float(h % 1000u) / 999.0f;
    };
    for (glm::ivec3 res : {glm::ivec3(13, 9, 7), glm::ivec3(5, 3, 1), glm::ivec3(2, 6, 4)}) {
        INFO(res.x << "x" << res.y << "x" << res.z);
        IndexScene s(res, kCube, noise, 1.2f);
        s.scene.materials[0].absorption = glm::vec3(2.0f, 0.5f, 1.0f);
        s.scene.materials[1].scattering = glm::vec3(0.3f, 3.0f, 0.1f);
        ClipPlaneSpec plane;
        plane.point = glm::vec3(0.1f, 0.0f, 0.0f);
        plane.normal = glm::normalize(glm::vec3(1.0f, 0.4f, 0.2f));
        plane.materials = {"haze"};
        s.scene.clipPlanes.push_back(plane);
        s.setup = makeViewSetup(s.scene, s.volume,
                                makeCameraFrame(s.scene.camera, s.volume.bounds, 8, 8));
        const RefractionVolumeCpu g = s.gradient();
        const std::vector<glm::vec4> separable = octreeLeafRangesCpu(s.setup, g, s.slotGrids());
        const std::vector<glm::vec4> oracle =
            octreeLeafRangesPerVoxelCpu(s.setup, g, s.slotGrids());
        REQUIRE(separable.size() == oracle.size());
        size_t differing = 0, kappaSpread = 0;
        for (size_t i = 0; i < oracle.size(); ++i) {
            if (std::memcmp(&separable[i], &oracle[i], sizeof(glm::vec4)) != 0) ++differing;
            if (oracle[i].z < oracle[i].w) ++kappaSpread;
        }
        CHECK(differing == 0);
        CHECK(kappaSpread > oracle.size() / 2);  // the κ windows are not trivial
        // And without fields: κ ≡ 0, n's windows alone.
        CHECK(octreeLeafRangesCpu(s.setup, g, {}) == octreeLeafRangesPerVoxelCpu(s.setup, g, {}));
    }
}
