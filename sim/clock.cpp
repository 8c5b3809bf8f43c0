#include "sim/clock.h"

#include <cmath>

#include "core/error.h"

namespace eikon {

SimulationClock::SimulationClock(double fps, double maxCfl) : fps_(fps), maxCfl_(maxCfl) {
    if (!(fps > 0.0) || !std::isfinite(fps))
        throw Error("clock", "fps must be a positive number, got " + std::to_string(fps));
    if (!(maxCfl > 0.0) || !std::isfinite(maxCfl))
        throw Error("clock", "the CFL number must be positive, got " + std::to_string(maxCfl));
}

int SimulationClock::substepsFor(double maxSpeed, double voxelSize) const {
    if (!(voxelSize > 0.0)) throw Error("clock", "voxel size must be positive");
    if (!std::isfinite(maxSpeed))
        throw Error("clock", "the maximum speed is not finite: the simulation blew up");
    if (maxSpeed <= 0.0) return 1;
    const double cfl = maxSpeed * frameDuration() / voxelSize;
    const double steps = std::ceil(cfl / maxCfl_ - 1e-12);
    // A blow-up shows as an absurd speed; cap the count so a frame never hangs.
    return int(std::min(std::max(steps, 1.0), 100000.0));
}

}  // namespace eikon
