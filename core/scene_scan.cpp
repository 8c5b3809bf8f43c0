#include "core/scene_scan.h"

#include "core/scan_layout.h"
#include "core/scene_helpers.h"

namespace eikon::scene_detail {

using json::Object;
using json::Range;
using json::Value;

void readScanSource(Object& object, const std::filesystem::path& sceneDirectory,
                    SourceSpec& source) {
    const Value file = object.required("file", "the path of an NRRD or raw file");
    source.file = resolveAgainst(sceneDirectory, file.nonEmptyString());
    if (isNrrdFile(source.file)) {
        const std::string why = "the NRRD header says how its samples are stored; remove '";
        object.forbid("dims", why + "dims'");
        object.forbid("value_type", why + "value_type'");
        object.forbid("endian", why + "endian'");
    }
    if (auto dims = object.optional("dims"))
        source.scanDims = dims->ivec3(1, kMaxScanSamplesAcross);
    if (auto type = object.optional("value_type")) {
        source.scanValueType = type->nonEmptyString();
        if (!parseScanValueType(source.scanValueType))
            type->fail(
                "expected a value type (uint8, int8, uint16, int16, uint32, int32, "
                "float32, float64), got \"" +
                source.scanValueType + "\"");
    }
    if (auto endian = object.optional("endian"))
        source.scanBigEndian = endian->choice({"little", "big"}) == "big";
    if (auto spacing = object.optional("spacing"))
        source.scanSpacing = spacing->vec3(Range::greaterThan(0.0));
    if (auto origin = object.optional("origin")) source.scanOrigin = origin->vec3();
    if (auto window = object.optional("window")) {
        const std::vector<Value> ends = window->elements("[low, high]", 2);
        if (ends.size() != 2) window->failExpected("[low, high]");
        const float low = ends[0].floatNumber();
        const float high = ends[1].floatNumber(Range::greaterThan(double(low)));
        source.scanWindow = glm::vec2(low, high);
    }
}

}  // namespace eikon::scene_detail
