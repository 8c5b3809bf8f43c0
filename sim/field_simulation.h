#pragma once
// A simulation that writes fields the renderer reads (the scene's smoke: density, temperature,
// velocity): one interface, so that the scene driver (pipeline/scene_driver.h) holds a list of them
// built by one factory. Stepped live, frame by frame, when a source of type "simulation" shows
// it; frame f holds the state after f − frame_start + 1 frames, as in `eikon simulate`'s cache.
#include <memory>
#include <string>
#include <vector>

#include "core/scene.h"

namespace eikon {
class FieldRegistry;
}

namespace eikon::sim {

class FieldSimulation {
public:
    virtual ~FieldSimulation() = default;
    // Brings the simulation to `frame`: forward from where it is, or from its start when the
    // frame lies behind. Returns whether its state changed (a frame already reached: no). Throws
    // eikon::Error for a frame before its start.
    virtual bool advanceToFrame(int frame) = 0;
    // Stores the fields it writes in `fields` as new versions; `origin` names them in messages.
    virtual void publish(FieldRegistry& fields, const std::string& origin) const = 0;
};

// The simulations the scene's sources show live (type "simulation"); none otherwise. With
// `fromCache`, each domain's frames are read from the cache `eikon simulate` wrote (its
// simulation.cache folder, <name>_####.vdb) instead of stepped: a render farm simulates once and
// renders the frames in parallel. The fields are the ones stepping publishes, bit for bit
// (sim/smoke_publish.h), so the pictures are the same bytes. A frame the cache lacks, or a cache
// a stopped run left mixed, is an error naming the file.
std::vector<std::unique_ptr<FieldSimulation>> makeFieldSimulations(const Scene& scene,
                                                                   bool fromCache = false);

}  // namespace eikon::sim
