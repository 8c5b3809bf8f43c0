#include "core/scene_transfer.h"

#include "core/particle_color.h"
#include "core/transfer_function.h"

namespace eikon::scene_detail {

using json::Range;
using json::Value;

void readTransfer(json::Object& object, MaterialSpec& material) {
    const auto transfer = object.optional("transfer");
    if (!transfer) return;
    if (material.gladstoneDale > 0.0f)
        transfer->fail(
            "a Gladstone–Dale material's field is a temperature; it takes no transfer "
            "function");
    const std::string form =
        "an array of 2 to " + std::to_string(kMaxTransferPoints) + " points [value, amount]";
    const std::vector<Value> points = transfer->elements(form, kMaxTransferPoints);
    if (points.size() < 2) transfer->failExpected(form);
    for (const Value& point : points) {
        const std::vector<Value> pair = point.elements("a point [value, amount]", 2);
        if (pair.size() != 2) point.failExpected("a point [value, amount]");
        material.transfer.emplace_back(pair[0].floatNumber(),
                                       pair[1].floatNumber(Range::atLeast(0.0)));
    }
    const std::string problem = transferFunctionProblem(material.transfer);
    if (!problem.empty()) transfer->fail("the transfer function " + problem);
}

void readParticleColor(json::Object& object, MaterialSpec& material) {
    const auto color = object.optional("particle_color");
    if (!color) return;
    ParticleColorSpec& spec = material.particleColor;
    const std::string pointForm = "a point [value, r, g, b]";
    if (color->json().is_string()) {
        spec.map = color->choice(colorMapNames());
    } else if (color->isObject()) {
        json::Object map(*color, "a colour map");
        spec.map = map.required("map", "a colour map's name").choice(colorMapNames());
        if (auto range = map.optional("range")) {
            const std::vector<Value> ends = range->elements("[low, high]", 2);
            if (ends.size() != 2) range->failExpected("[low, high]");
            spec.range = glm::vec2(ends[0].floatNumber(), ends[1].floatNumber());
        }
        map.finish();
    } else {
        const std::string form =
            "a colour map's name, {\"map\": name, \"range\": [low, high]} or "
            "an array of 2 to " +
            std::to_string(kMaxParticleColorPoints) + " points [value, r, g, b]";
        const std::vector<Value> points = color->elements(form, kMaxParticleColorPoints);
        if (points.size() < 2) color->failExpected(form);
        for (const Value& point : points) {
            const std::vector<Value> v = point.elements(pointForm, 4);
            if (v.size() != 4) point.failExpected(pointForm);
            spec.points.emplace_back(v[0].floatNumber(), v[1].floatNumber(Range::atLeast(0.0)),
                                     v[2].floatNumber(Range::atLeast(0.0)),
                                     v[3].floatNumber(Range::atLeast(0.0)));
        }
    }
    const std::string problem = particleColorProblem(spec);
    if (!problem.empty()) color->fail("the particle colour " + problem);
}

}  // namespace eikon::scene_detail
