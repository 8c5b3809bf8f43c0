#pragma once
// Comparing a case's new outputs with its references (apps/regress_references.h) as the case
// asks (apps/regress_case.h): exact hashes, image metrics, grids voxel by voxel, counters. Each
// problem is a Finding with a one-line reason; what a report shows beside it (the images, the
// worst voxels) travels with it.
#include <set>
#include <string>
#include <vector>

#include "apps/regress_case.h"
#include "apps/regress_references.h"
#include "apps/regress_run.h"
#include "core/grid_compare.h"

namespace eikon::app {

struct Finding {
    std::string key;     // "CASE/cpu/frame_0001.png", or "CASE/cpu ↔ gpu frame_0001.exr"
    std::string reason;  // one line
    // For the report: the two images (empty when there is nothing to show), and whether they
    // are linear (EXR, shown through the tone map) or display values (PNG).
    std::string referenceImage;
    std::string newImage;
    bool linear = false;
    std::vector<GridDifference> grids;  // a cache comparison's grids that differ
};

// The outputs of `run` whose reference is their hash alone: caches compared by hash.
std::set<std::string> hashOnlyOutputs(const RegressCase& c, const CaseRun& run);

// Every difference between `run`'s outputs and the references of `c`; empty when it passes.
std::vector<Finding> checkCase(const RegressCase& c, const CaseRun& run,
                               const ReferenceManifest& references, const std::string& suiteArg);

}  // namespace eikon::app
