#pragma once
// The accumulators of a CPU particle trace (photons, wavefront patches): the deposit volumes
// (PhotonKernelCpu::kDepositChannels per voxel; one per thread, DepositBuffersCpu) and the
// receiver maps' sums as 64-bit integers, zeroed, with fixed-point scales from the emitted power
// (render/transport/fixed_point.h), the energy totals, and their read-out as floats.
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/transport/photons/photon_kernel_cpu.h"

namespace eikon {

class FixedDepositsCpu {
public:
    // `emitted`: the power of every particle that entered, summed in index order before anything
    // is deposited, so that the scales do not depend on the order of the deposits.
    FixedDepositsCpu(const ViewSetup& setup, glm::dvec3 emitted);

    // Points the kernel's deposit hooks (depositVoxel, depositReceiverTexel) here.
    void attach(shared::PhotonKernelCpu& kernel);

    // What an ended particle leaves: `lost` (extinguished on its way) and, unless it passes its
    // power on (a split patch), `left` into the bin its state names: escaped, received, or
    // dropped for any other end (dropped, cut, removed, torn).
    void finish(int state, glm::vec3 left, glm::vec3 lost, bool passesPowerOn = false);
    // Of the dropped power, what a wavefront removed at a caustic (reported on its own).
    void addRemoved(glm::vec3 power);
    // Power reflected at surfaces (Fresnel) and not followed: a bin of its own.
    void addReflected(glm::vec3 power);
    void addSteps(int64_t steps) { totals_.steps.fetch_add(steps, std::memory_order_relaxed); }
    void addCut() { totals_.cut.fetch_add(1, std::memory_order_relaxed); }

    glm::dvec4 scale() const { return scale_; }  // rgb: power·length channels; w: direction
    int64_t steps() const { return totals_.steps.load(); }
    int64_t cut() const { return totals_.cut.load(); }
    // Escaped, extinguished, dropped and received into `totals` (emitted is the caller's).
    void readTotals(PhotonTotals& totals) const;
    std::vector<glm::vec4> receiverMap(const ViewSetup& setup) const;
    // Σ power·length (rgb) and the weighted direction (xyz) per voxel.
    void readVolumes(std::vector<glm::vec4>& radiance, std::vector<glm::vec4>& direction) const;

private:
    size_t voxels_ = 0;
    size_t receiverSums_ = 0;
    glm::dvec4 scale_{0.0};
    glm::dvec3 totalScale_{0.0};
    std::unique_ptr<DepositBuffersCpu> deposits_;
    std::unique_ptr<std::atomic<int64_t>[]> receiverDeposits_;
    FixedTotals totals_;
};

}  // namespace eikon
