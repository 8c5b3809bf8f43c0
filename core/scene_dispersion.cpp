#include "core/scene_dispersion.h"

#include <cstdio>
#include <string>

namespace eikon::scene_detail {

namespace {

using json::Range;
using json::Value;

// "n = 0.98 in the blue channel" for the first channel below 1, or "".
std::string channelBelowOne(const glm::vec3& n) {
    static const char* const kChannels[3] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c)
        if (!(n[c] >= 1.0f)) {
            char text[64];
            std::snprintf(text, sizeof text, "n = %.6g in the %s channel", double(n[c]),
                          kChannels[c]);
            return text;
        }
    return "";
}

}  // namespace

void readDispersion(json::Object& object, MaterialSpec& material, bool iorGiven) {
    const auto abbe = object.optional("abbe");
    const auto cauchy = object.optional("cauchy");
    if (abbe && cauchy) cauchy->fail("give either \"abbe\" (with \"ior\") or \"cauchy\", not both");
    if (abbe) {
        material.abbe = abbe->floatNumber(Range::greaterThan(0.0));
        if (material.gladstoneDale > 0.0f)
            abbe->fail("\"abbe\" is for a glass or a liquid, not Gladstone-Dale air");
        if (!iorGiven || !(material.ior > 1.0f))
            abbe->fail("\"abbe\" needs \"ior\" (n_d, the green channel's) above 1");
        const std::string below = channelBelowOne(material.channelIor());
        if (!below.empty()) abbe->fail("gives " + below + " (an index below vacuum's)");
    }
    if (cauchy) {
        if (iorGiven) cauchy->fail("give either \"ior\" or \"cauchy\" (which sets n_d), not both");
        if (material.gladstoneDale > 0.0f)
            cauchy->fail("\"cauchy\" is for a glass or a liquid, not Gladstone-Dale air");
        const std::string form = "[A, B]: n(λ) = A + B/λ², λ in µm";
        const std::vector<Value> ab = cauchy->elements(form, 2);
        if (ab.size() != 2) cauchy->failExpected(form);
        const double a = ab[0].number(Range::greaterThan(0.0));
        const double b = ab[1].number(Range::atLeast(0.0));
        const IndexAndAbbe law = fromCauchy(a, b);
        material.ior = float(law.ior);
        material.abbe = float(law.abbe);
        const std::string below = channelBelowOne(material.channelIor());
        if (!below.empty()) cauchy->fail("gives " + below + " (an index below vacuum's)");
    }
}

}  // namespace eikon::scene_detail
