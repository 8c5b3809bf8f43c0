#pragma once
// The GPU photon pass against its CPU twin, for the GPU photon tests (test_photons_gpu.cpp,
// test_photon_rounds.cpp): a runner that also checks the GPU's refraction volumes, and the
// bit-for-bit comparison of two photon results.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "render/params_buffer.h"
#include "render/refraction_volume.h"
#include "render/transport/photons/photon_tracing_gpu.h"
#include "render/volume_textures.h"
#include "support/photon_scene.h"

namespace eikon::test {

// The photon test scene of test_photons.cpp, with its refraction volumes on both sides.
using GpuPhotonScene = PhotonScene;

// Runs the GPU pass; also checks that the GPU's own refraction volumes equal the CPU twin's, which
// every comparison relies on.
struct GpuRun {
    explicit GpuRun(bool exactMath = true) : tracer(exactMath) {}

    VolumeTextures textures;
    ParamsBuffer params;
    RefractionVolumesGpu refraction;
    PhotonTracerGpu tracer;

    PhotonResultCpu trace(const GpuPhotonScene& s, const PhotonSettings& settings) {
        textures.update({&s.field});
        params.upload(s.setup.params);
        refraction.compute(s.setup, textures);
        REQUIRE(refraction.downloadGradient() == s.gradient);
        REQUIRE(refraction.downloadOctree() == s.octree);
        tracer.trace(s.setup, textures, refraction, settings);
        return tracer.download();
    }
};

inline bool sameBits(const void* a, const void* b, size_t bytes) {
    return std::memcmp(a, b, bytes) == 0;
}

template <typename T>
inline bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && sameBits(a.data(), b.data(), a.size() * sizeof(T));
}

inline bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// Everything the GPU result must share with the CPU twin's, bit for bit.
inline void requireIdentical(const PhotonResultCpu& gpu, const PhotonResultCpu& cpu) {
    REQUIRE(gpu.photons.size() == cpu.photons.size());
    CHECK(gpu.photonsTraced == cpu.photonsTraced);
    CHECK(gpu.photonsTraced > 0);
    CHECK(gpu.fixedPointScale == cpu.fixedPointScale);
    CHECK(gpu.totals.emitted == cpu.totals.emitted);
    CHECK(gpu.totals.escaped == cpu.totals.escaped);
    CHECK(gpu.totals.extinguished == cpu.totals.extinguished);
    CHECK(gpu.totals.dropped == cpu.totals.dropped);
    CHECK(gpu.steps == cpu.steps);
    CHECK(gpu.photonsCut == cpu.photonsCut);
    CHECK(gpu.rounds == cpu.rounds);
    int photonMismatches = 0;
    for (size_t i = 0; i < gpu.photons.size(); ++i)
        if (!sameBits(&gpu.photons[i], &cpu.photons[i], sizeof(shared::GpuPhoton)))
            ++photonMismatches;
    int radianceMismatches = 0, directionMismatches = 0;
    bool allFinite = true;
    for (size_t i = 0; i < gpu.radiance.size() && i < cpu.radiance.size(); ++i) {
        radianceMismatches += gpu.radiance[i] != cpu.radiance[i];
        directionMismatches += gpu.direction[i] != cpu.direction[i];
        allFinite = allFinite && finite(gpu.radiance[i]) && finite(gpu.direction[i]);
    }
    INFO(photonMismatches << " photons, " << radianceMismatches << " radiance voxels, "
                          << directionMismatches << " direction voxels differ; " << gpu.steps
                          << " steps");
    CHECK(photonMismatches == 0);
    CHECK(radianceMismatches == 0);
    CHECK(directionMismatches == 0);
    CHECK(sameBits(gpu.radiance, cpu.radiance));
    CHECK(sameBits(gpu.direction, cpu.direction));
    CHECK(allFinite);
}

}  // namespace eikon::test
