#pragma once
// The analytic suite of `eikon bench methods`: scenes whose light has a closed form, and how far a
// light-transport method's output is from it. Every case reads the method only through the
// output contract (fluenceRateCpu in render/light_transport.h) or its energy accounting, so a
// method added later is measured with no new code here.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/dense_grid.h"
#include "core/exact_ray.h"
#include "core/scene.h"
#include "render/light_transport.h"

namespace eikon::app {

// What a method gave for one case: the fluence rate at every voxel centre (x fastest), and its
// energy accounting where it keeps one.
struct CaseOutput {
    RenderVolume volume;
    std::vector<glm::vec3> fluenceRate;
    std::optional<EnergyBalance> energy;
};

struct MethodCase {
    std::string name;        // "slab", "ball_lens", ...
    std::string closedForm;  // what the error is measured against, one line
    std::string errorUnit;   // "voxels" or "relative"
    Scene scene;             // materials, lights; the light-transport section is the bench's
    RenderVolume volume;
    // The dense grid of every field a material reads (field name -> values on `volume`).
    std::map<std::string, DenseGrid> fields;
    // The error of one output; NaN where the method shows nothing to measure (a lens that does
    // not focus), which the report writes as such instead of a number.
    std::function<double(const CaseOutput&)> error;
    // The continuous index field the "n" grid samples ((∇n, n) at a world point), for the exact
    // traces of `eikon bench integrators`; empty where the case has no refraction.
    IndexField index;
};

// The suite at `resolution` voxels per edge (made odd, so that the optical axis runs through a
// column of voxel centres), or only the cases named in `only` when it is not empty. Throws
// eikon::Error naming an unknown case.
std::vector<MethodCase> methodCases(int resolution, const std::vector<std::string>& only = {});
// The cases whose light bends (those with a continuous index field): ball_lens, luneburg,
// linear_n2, grin.
std::vector<std::string> refractingCaseNames();
// The names of every case, in order.
std::vector<std::string> methodCaseNames();

}  // namespace eikon::app
