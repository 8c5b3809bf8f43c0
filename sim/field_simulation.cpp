#include "sim/field_simulation.h"

#include <map>
#include <optional>

#include "core/error.h"
#include "core/field_registry.h"
#include "core/frame_list.h"
#include "core/vdb_import.h"
#include "core/vdb_sequence.h"
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

// One smoke domain's frames read from its cache instead of stepped.
class CachedSmokeFrames final : public FieldSimulation {
public:
    CachedSmokeFrames(const Scene& scene, std::size_t domain)
        : spec_(scene.simulations[domain]),
          first_(scene.time.frameStart),
          pattern_(framePath(spec_.cacheDirectory, spec_.cacheName, 0, "vdb")) {
        // <name>_0000.vdb -> <name>_####.vdb
        pattern_.replace(pattern_.size() - 8, 4, "####");
    }

    bool advanceToFrame(int frame) override {
        if (frame < first_)
            throw Error(spec_.jsonPath, "the simulation starts at frame " + std::to_string(first_) +
                                            "; frame " + std::to_string(frame) +
                                            " comes before it");
        if (loaded_ && frame_ == frame) return false;
        if (!sequence_) {
            try {
                sequence_ = findVdbSequence(pattern_);  // refuses a cache a stopped run mixed
            } catch (const Error& e) {
                throw Error(e.where(), e.reason() +
                                           " (--from-cache reads what eikon simulate "
                                           "wrote: run it on the scene first)");
            }
        }
        const auto file = sequence_->frames.find(frame);
        if (file == sequence_->frames.end())
            throw Error(pattern_, "the cache has no frame " + std::to_string(frame) + " (it has " +
                                      sequence_->framesText() +
                                      "); run eikon simulate through frame " +
                                      std::to_string(frame));
        FieldRegistry read;
        importVdb(file->second, read);
        for (const char* name : {field::kDensity, field::kTemperature, field::kVelocity})
            grids_[name] = read.get(name).grid;
        file_ = file->second;
        frame_ = frame;
        loaded_ = true;
        return true;
    }

    void publish(FieldRegistry& fields, const std::string&) const override {
        for (const auto& [name, grid] : grids_)
            fields.set(spec_.label.empty() ? name : name + "." + spec_.label, grid,
                       file_ + ":" + name);
    }

private:
    SmokeSimulationSpec spec_;
    int first_;
    std::string pattern_;
    std::optional<VdbSequence> sequence_;
    std::map<std::string, openvdb::GridBase::Ptr> grids_;
    std::string file_;
    int frame_ = 0;
    bool loaded_ = false;
};

}  // namespace

std::vector<std::unique_ptr<FieldSimulation>> makeFieldSimulations(const Scene& scene,
                                                                   bool fromCache) {
    std::vector<std::unique_ptr<FieldSimulation>> simulations;
    bool shown = false;
    for (const SourceSpec& source : scene.sources) shown |= source.type == SourceType::Simulation;
    // A source of type "simulation" shows every domain; each publishes its own (labelled) fields.
    if (!shown) return simulations;
    for (std::size_t d = 0; d < scene.simulations.size(); ++d) {
        if (fromCache)
            simulations.push_back(std::make_unique<CachedSmokeFrames>(scene, d));
        else
            simulations.push_back(std::make_unique<SmokeFieldSimulation>(scene, d));
    }
    return simulations;
}

}  // namespace eikon::sim
