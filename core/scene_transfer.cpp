#include "core/scene_transfer.h"

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

}  // namespace eikon::scene_detail
