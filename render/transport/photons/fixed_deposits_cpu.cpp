#include "render/transport/photons/fixed_deposits_cpu.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/receiver_map.h"

namespace eikon {
FixedDepositsCpu::FixedDepositsCpu(const ViewSetup& setup, glm::dvec3 emitted) {
    const glm::ivec3 res(setup.params.resolution);
    voxels_ = size_t(res.x) * size_t(res.y) * size_t(res.z);
    shared::PhotonKernelCpu kernel{{setup.params}};
    const glm::vec3 h = kernel.volumeVoxelSize();
    const double smallestVoxel = double(std::min({h.x, h.y, h.z}));
    scale_ = glm::dvec4(fixedPointScaleFor(emitted.x, smallestVoxel),
                        fixedPointScaleFor(emitted.y, smallestVoxel),
                        fixedPointScaleFor(emitted.z, smallestVoxel),
                        fixedPointScaleFor(rec709Luminance(emitted), smallestVoxel));
    totalScale_ = glm::dvec3(fixedPointScaleFor(emitted.x, 1.0), fixedPointScaleFor(emitted.y, 1.0),
                             fixedPointScaleFor(emitted.z, 1.0));
    const size_t depositCount = voxels_ * size_t(shared::PhotonKernelCpu::kDepositChannels);
    deposits_ = std::make_unique<DepositBuffersCpu>(depositCount);
    receiverSums_ = 3 * receiverMapTexels(setup.params);
    receiverDeposits_.reset(new std::atomic<int64_t>[std::max<size_t>(receiverSums_, 1)]);
    for (size_t i = 0; i < receiverSums_; ++i)
        receiverDeposits_[i].store(0, std::memory_order_relaxed);
}

void FixedDepositsCpu::attach(shared::PhotonKernelCpu& kernel) {
    kernel.scale = scale_;
    kernel.deposits = deposits_.get();
    kernel.receiverDeposits = receiverDeposits_.get();
    kernel.receiverScale = totalScale_;
}

void FixedDepositsCpu::finish(int state, glm::vec3 left, glm::vec3 lost, bool passesPowerOn) {
    for (int c = 0; c < 3; ++c) {
        totals_.extinguished[c].fetch_add(shared::PhotonKernelCpu::toFixed(lost[c], totalScale_[c]),
                                          std::memory_order_relaxed);
        if (passesPowerOn) continue;
        std::atomic<int64_t>& bin = state == EK_PHOTON_ESCAPED    ? totals_.escaped[c]
                                    : state == EK_PHOTON_RECEIVED ? totals_.received[c]
                                                                  : totals_.dropped[c];
        bin.fetch_add(shared::PhotonKernelCpu::toFixed(left[c], totalScale_[c]),
                      std::memory_order_relaxed);
    }
}

namespace {
void addFixed(std::atomic<int64_t> (&bins)[3], glm::vec3 power, glm::dvec3 scale) {
    for (int c = 0; c < 3; ++c)
        bins[c].fetch_add(shared::PhotonKernelCpu::toFixed(power[c], scale[c]),
                          std::memory_order_relaxed);
}
}  // namespace

void FixedDepositsCpu::addRemoved(glm::vec3 power) {
    addFixed(totals_.removed, power, totalScale_);
}

void FixedDepositsCpu::addReflected(glm::vec3 power) {
    if (power == glm::vec3(0.0f)) return;
    addFixed(totals_.reflected, power, totalScale_);
}

void FixedDepositsCpu::readTotals(PhotonTotals& totals) const {
    for (int c = 0; c < 3; ++c) {
        totals.escaped[c] = fromFixedPoint(totals_.escaped[c].load(), totalScale_[c]);
        totals.extinguished[c] = fromFixedPoint(totals_.extinguished[c].load(), totalScale_[c]);
        totals.dropped[c] = fromFixedPoint(totals_.dropped[c].load(), totalScale_[c]);
        totals.received[c] = fromFixedPoint(totals_.received[c].load(), totalScale_[c]);
        totals.removed[c] = fromFixedPoint(totals_.removed[c].load(), totalScale_[c]);
        totals.reflected[c] = fromFixedPoint(totals_.reflected[c].load(), totalScale_[c]);
    }
}

std::vector<glm::vec4> FixedDepositsCpu::receiverMap(const ViewSetup& setup) const {
    std::vector<int64_t> sums(receiverSums_);
    for (size_t i = 0; i < receiverSums_; ++i) sums[i] = receiverDeposits_[i].load();
    return receiverMapFromFixed(setup.params, sums, totalScale_);
}

void FixedDepositsCpu::readVolumes(std::vector<glm::vec4>& radiance,
                                   std::vector<glm::vec4>& direction) const {
    radiance.assign(voxels_, glm::vec4(0.0f));
    direction.assign(voxels_, glm::vec4(0.0f));
    constexpr size_t kChannels = shared::PhotonKernelCpu::kDepositChannels;
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, voxels_, 4096), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t i = r.begin(); i != r.end(); ++i)
                for (int c = 0; c < 3; ++c) {
                    const size_t cell = i * kChannels;
                    radiance[i][c] = float(fromFixedPoint(deposits_->sum(cell + c), scale_[c]));
                    direction[i][c] = float(fromFixedPoint(deposits_->sum(cell + 3 + c), scale_.w));
                }
        });
}

}  // namespace eikon
