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
    // The time at which substep `substep` (0-based) of `substeps` that step frame `frame` ends.
    // Stepping frame f takes the state from the time of frame f − 1 to the time of frame f, so
    // the last substep ends exactly at timeOfFrame(frame) and a simulated frame shows the same
    // moment as a rendered one.
    double timeOfSubstep(int frame, int substep, int substeps) const {
        return ((frame - 1) + double(substep + 1) / substeps) / fps_;
    }

    // Substeps for one frame so that maxSpeed·dt/voxelSize stays ≤ the CFL number (at least one;
    // a non-finite speed is an eikon::Error: the simulation blew up).
    int substepsFor(double maxSpeed, double voxelSize) const;

private:
    double fps_;
    double maxCfl_;
};

}  // namespace eikon
