#pragma once
// The one clock that steps simulations and animation, so that a scene replays identically:
// frames at a fixed rate, each frame split into equal substeps chosen from a CFL number.
namespace eikon {

class SimulationClock {
public:
    SimulationClock(double fps, double maxCfl);

    double fps() const { return fps_; }
    double frameDuration() const { return 1.0 / fps_; }
    double timeOfFrame(int frame) const { return frame / fps_; }

    // Substeps for one frame so that maxSpeed·dt/voxelSize stays ≤ the CFL number (at least one;
    // a non-finite speed is an eikon::Error: the simulation blew up).
    int substepsFor(double maxSpeed, double voxelSize) const;

private:
    double fps_;
    double maxCfl_;
};

}  // namespace eikon
