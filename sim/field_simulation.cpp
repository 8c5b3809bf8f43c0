#include "sim/field_simulation.h"

#include "core/error.h"
#include "sim/smoke_from_scene.h"
#include "sim/smoke_publish.h"
#include "sim/smoke_solver.h"

namespace eikon::sim {
namespace {

// One smoke domain of the scene (an entry of Scene::simulations), rebuilt from the scene on going
// back.
class SmokeFieldSimulation final : public FieldSimulation {
public:
    SmokeFieldSimulation(const Scene& scene, std::size_t domain) : scene_(scene), domain_(domain) {}

    bool advanceToFrame(int frame) override {
        const int first = scene_.time.frameStart;
        if (frame < first)
            throw Error(scene_.path + ":/time/frame_start",
                        "the simulation starts at frame " + std::to_string(first) + "; frame " +
                            std::to_string(frame) + " comes before it");
        if (solver_ && frame_ == frame) return false;
        if (!solver_ || frame < frame_) {
            solver_ = std::make_unique<SmokeSolver>(smokeSolverFrom(scene_, domain_));
            frame_ = first - 1;
        }
        while (frame_ < frame) {
            solver_->advanceFrame();
            ++frame_;
        }
        return true;
    }

    void publish(FieldRegistry& fields, const std::string& origin) const override {
        const SmokeSimulationSpec& spec = scene_.simulations[domain_];
        const std::string where = spec.label.empty() ? origin : origin + " (" + spec.jsonPath + ")";
        publishSmoke(solver_->grid(), fields, where, spec.label);
    }

private:
    Scene scene_;  // as loaded: the solver is rebuilt from it on going back
    std::size_t domain_;
    std::unique_ptr<SmokeSolver> solver_;
    int frame_ = 0;  // the frame the solver's state is, once solver_ exists
};

}  // namespace

std::vector<std::unique_ptr<FieldSimulation>> makeFieldSimulations(const Scene& scene) {
    std::vector<std::unique_ptr<FieldSimulation>> simulations;
    bool shown = false;
    for (const SourceSpec& source : scene.sources) shown |= source.type == SourceType::Simulation;
    // A source of type "simulation" shows every domain; each publishes its own (labelled) fields.
    if (shown)
        for (std::size_t d = 0; d < scene.simulations.size(); ++d)
            simulations.push_back(std::make_unique<SmokeFieldSimulation>(scene, d));
    return simulations;
}

}  // namespace eikon::sim
