// The benchmark's OpenVDB peer (sim/openvdb_advection_peer.h) must advect the same problem as
// advectField(), or its ratios would compare different things: same grid, same velocity faces.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/advection_problems.h"
#include "sim/openvdb_advection_peer.h"

using namespace eikon::sim;

TEST_CASE("OpenVDB peer: Zalesak's disk through VolumeAdvection matches advectField's error",
          "[smoke][advection][peer]") {
    // Measured (this commit): at 24 and 48 cells, MAC + clamp L1 1.24 and 0.90 for OpenVDB
    // against 1.30 and 0.91 for ours; a half-cell shift of the staggered faces or a wrong sign
    // would move the disk and put OpenVDB's error far from ours.
    constexpr double kSameSchemeTolerance = 0.15;  // relative difference of L1
    auto peer = [](VdbIntegrator i, VdbLimiter l, int n) {
        auto advector = makeOpenVdbAdvector(i, l);
        return zalesakRotation(n, ZalesakShape::Disk, *advector);
    };
    const AdvectionProblemResult semi = peer(VdbIntegrator::Semi, VdbLimiter::None, 48);
    double previous = 1e9;
    for (int n : {24, 48}) {
        const AdvectionProblemResult vdb = peer(VdbIntegrator::MacCormack, VdbLimiter::Clamp, n);
        const AdvectionProblemResult ours =
            zalesakRotation(n, ZalesakShape::Disk, {AdvectionScheme::MacCormack, Limiter::Clamp});
        WARN("Zalesak disk " << n << ": OpenVDB MAC + clamp L1 " << vdb.l1 << " (mass change "
                             << vdb.massChange << "), ours " << ours.l1 << "; OpenVDB SEMI at 48 "
                             << semi.l1);
        CHECK(std::isfinite(vdb.l1));
        CHECK(std::fabs(vdb.l1 - ours.l1) <= kSameSchemeTolerance * ours.l1);
        CHECK(vdb.l1 < previous);
        previous = vdb.l1;
    }
    CHECK(previous < semi.l1);  // second order beats first order there too
}
