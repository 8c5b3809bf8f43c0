#include "sim/field_simulation.h"

#include "core/error.h"
#include "sim/smoke_from_scene.h"
#include "sim/smoke_publish.h"
#include "sim/smoke_solver.h"

namespace eikon::sim {
namespace {

// The scene's smoke (its "simulation" section), rebuilt from the scene on going back.
class SmokeFieldSimulation final : public FieldSimulation {
public:
    explicit SmokeFieldSimulation(const Scene& scene) : scene_(scene) {}

    bool advanceToFrame(int frame) override {
        const int first = scene_.time.frameStart;
        if (frame < first)
            throw Error(scene_.path + ":/time/frame_start",
                        "the simulation starts at frame " + std::to_string(first) + "; frame " +
                            std::to_string(frame) + " comes before it");
        if (solver_ && frame_ == frame) return false;
        if (!solver_ || frame < frame_) {
            solver_ = std::make_unique<SmokeSolver>(smokeSolverFrom(scene_));
            frame_ = first - 1;
        }
        while (frame_ < frame) {
            solver_->advanceFrame();
            ++frame_;
        }
        return true;
    }

    void publish(FieldRegistry& fields, const std::string& origin) const override {
        publishSmoke(solver_->grid(), fields, origin);
    }

private:
    Scene scene_;  // as loaded: the solver is rebuilt from it on going back
    std::unique_ptr<SmokeSolver> solver_;
    int frame_ = 0;  // the frame the solver's state is, once solver_ exists
};

}  // namespace

std::vector<std::unique_ptr<FieldSimulation>> makeFieldSimulations(const Scene& scene) {
    std::vector<std::unique_ptr<FieldSimulation>> simulations;
    for (const SourceSpec& source : scene.sources)
        if (source.type == SourceType::Simulation) {
            // One smoke section per scene today: the sources that show it share it.
            simulations.push_back(std::make_unique<SmokeFieldSimulation>(scene));
            break;
        }
    return simulations;
}

}  // namespace eikon::sim
