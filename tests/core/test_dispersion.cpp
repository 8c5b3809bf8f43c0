// Dispersion (core/dispersion.h): n per colour channel from n_d and the Abbe number, or from a
// Cauchy pair, against a glass catalogue and the law itself; and the scene keys' one-line errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/dispersion.h"
#include "core/error.h"
#include "core/scene.h"

using namespace eikon;

namespace {

std::string errorOf(const std::string& material) {
    try {
        eikon::parseScene(R"({"sources": [{"type": "sphere"}], "materials": [)" + material + "]}",
                          "glass.json");
    } catch (const eikon::Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("n per channel from n_d and the Abbe number matches N-BK7's catalogue lines",
          "[dispersion]") {
    // Schott N-BK7: n_d = 1.5168, V_d = 64.17; n_C = 1.51432, n_F = 1.52238 (the two-term Cauchy
    // law through them is within 6e-5 of the catalogue's Sellmeier fit at C and F).
    const glm::vec3 n = channelIndices(1.5168f, 64.17f);
    CHECK(n.g == 1.5168f);
    CHECK(n.r == Approx(1.51432).margin(1e-4));
    CHECK(n.b == Approx(1.52238).margin(1e-4));
    CHECK((n.g - 1.0) / (n.b - n.r) == Approx(64.17).epsilon(1e-4));
    // No dispersion: the same n in every channel, exactly.
    CHECK(channelIndices(1.5f, 0.0f) == glm::vec3(1.5f));
}

TEST_CASE("a Cauchy pair and its n_d and Abbe number are the same law", "[dispersion]") {
    // N-BK7 fitted: A = 1.5046, B = 0.00420 µm².
    const double a = 1.5046, b = 0.00420;
    const IndexAndAbbe law = fromCauchy(a, b);
    CHECK(law.ior == Approx(a + b / (0.5875618 * 0.5875618)).epsilon(1e-12));
    const glm::vec3 n = channelIndices(float(law.ior), float(law.abbe));
    for (int c = 0; c < 3; ++c) {
        const double lambda = kChannelWavelengthUm[c];
        CHECK(n[c] == Approx(a + b / (lambda * lambda)).margin(2e-7));
    }
    CHECK(fromCauchy(1.33, 0.0).abbe == 0.0);
}

TEST_CASE("a scene's materials and meshes take abbe or cauchy", "[dispersion][scene]") {
    const Scene scene = parseScene(
        R"({"sources": [{"type": "sphere"}], "materials": [
            {"name": "crown", "ior": 1.5168, "abbe": 64.17},
            {"name": "water", "cauchy": [1.3199, 0.0031]},
            {"name": "plain", "ior": 1.5}]})",
        "glass.json");
    CHECK(scene.materials[0].abbe == 64.17f);
    CHECK(scene.materials[1].ior == Approx(1.3199 + 0.0031 / (0.5875618 * 0.5875618)));
    CHECK(scene.materials[1].abbe > 0.0f);
    CHECK(scene.materials[2].abbe == 0.0f);
    CHECK(scene.materials[2].channelIor() == glm::vec3(1.5f));
}

TEST_CASE("bad dispersion is one line naming the key", "[dispersion][scene]") {
    CHECK(errorOf(R"({"name": "m", "ior": 1.5, "abbe": 0})") ==
          "glass.json:/materials/0/abbe: expected a number > 0, got 0");
    CHECK(errorOf(R"({"name": "m", "abbe": 40})") ==
          "glass.json:/materials/0/abbe: \"abbe\" needs \"ior\" (n_d, the green channel's) "
          "above 1");
    CHECK(errorOf(R"({"name": "m", "ior": 1.01, "abbe": 0.1})") ==
          "glass.json:/materials/0/abbe: gives n = 0.9799 in the red channel (an index below "
          "vacuum's)");
    CHECK(errorOf(R"({"name": "m", "ior": 1.5, "cauchy": [1.5, 0.004]})") ==
          "glass.json:/materials/0/cauchy: give either \"ior\" or \"cauchy\" (which sets n_d), "
          "not both");
    CHECK(errorOf(R"({"name": "m", "ior": 1.5, "abbe": 50, "cauchy": [1.5, 0.004]})") ==
          "glass.json:/materials/0/cauchy: give either \"abbe\" (with \"ior\") or \"cauchy\", "
          "not both");
    CHECK(errorOf(R"({"name": "m", "cauchy": [1.5, -0.004]})") ==
          "glass.json:/materials/0/cauchy/1: expected a number >= 0, got -0.004");
    CHECK(errorOf(R"({"name": "m", "cauchy": [0.9, 0.004]})").find("in the red channel") !=
          std::string::npos);
    CHECK(errorOf(R"({"name": "m", "cauchy": [1.5]})") ==
          "glass.json:/materials/0/cauchy: expected [A, B]: n(λ) = A + B/λ², λ in µm, got [1.5]");
    CHECK(errorOf(R"({"name": "m", "field": "temperature", "gladstone_dale": 0.0003, "abbe": 30})")
              .find("not Gladstone-Dale air") != std::string::npos);
}
