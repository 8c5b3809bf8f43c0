// Transfer functions (core/transfer_function.h): the piecewise-linear map against its closed form,
// the slot names that keep two classes of one field apart, and the scene's errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/scene.h"
#include "core/transfer_function.h"

using Catch::Matchers::Contains;

TEST_CASE("A transfer function is linear between its points and flat beyond them", "[transfer]") {
    const std::vector<glm::vec2> tf{{0.0f, 0.0f}, {0.4f, 0.0f}, {0.6f, 3.0f}, {1.0f, 1.0f}};
    CHECK(eikon::transferAmount(tf, -5.0f) == 0.0f);
    CHECK(eikon::transferAmount(tf, 0.2f) == 0.0f);
    CHECK(eikon::transferAmount(tf, 0.5f) == Approx(1.5f).epsilon(1e-6));
    CHECK(eikon::transferAmount(tf, 0.6f) == 3.0f);  // at a point: its amount exactly
    CHECK(eikon::transferAmount(tf, 0.8f) == Approx(2.0f).epsilon(1e-6));
    CHECK(eikon::transferAmount(tf, 7.0f) == 1.0f);
    CHECK(eikon::transferAmount(tf, std::numeric_limits<float>::quiet_NaN()) == 0.0f);
    CHECK(eikon::transferAmount({}, 0.37f) == 0.37f);  // none: the value itself

    eikon::MaterialSpec plain;
    plain.name = "smoke";
    CHECK(eikon::materialSlotName(plain) == "density");
    eikon::MaterialSpec dentin = plain;
    dentin.name = "dentin";
    dentin.field = "density.ct";
    dentin.transfer = tf;
    CHECK(eikon::materialSlotName(dentin) == "density.ct|dentin");

    eikon::DenseGrid field;
    field.values = {0.0f, 0.5f, 0.6f, 2.0f};
    const eikon::DenseGrid mapped = eikon::applyTransfer(field, tf, "density.ct|dentin", 77);
    CHECK(mapped.field == "density.ct|dentin");
    CHECK(mapped.version == 77);
    CHECK(mapped.values == std::vector<float>{0.0f, eikon::transferAmount(tf, 0.5f), 3.0f, 1.0f});
}

TEST_CASE("Transfer functions in a scene: read, and their errors", "[transfer]") {
    auto sceneWith = [](const std::string& material) {
        return eikon::parseScene(
            R"({"sources": [{"type": "box", "value": 1}], "materials": [)" + material + "]}",
            "tf.json");
    };
    const eikon::Scene scene = sceneWith(
        R"({"name": "bone", "absorption": [1, 1, 1], "transfer": [[0, 0], [0.5, 0], [0.8, 2]]})");
    REQUIRE(scene.materials[0].transfer.size() == 3);
    CHECK(scene.materials[0].transfer[2] == glm::vec2(0.8f, 2.0f));

    auto errorOf = [&](const std::string& transfer, const std::string& extra = "") {
        try {
            sceneWith(R"({"name": "m", "absorption": [1, 1, 1], )" + extra + R"("transfer": )" +
                      transfer + "}");
        } catch (const eikon::Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    CHECK_THAT(errorOf("[[0, 0]]"),
               Contains("/materials/0/transfer: expected an array of 2 to 16"));
    CHECK_THAT(errorOf("[[0, 0], [0.5, 1], [0.5, 2]]"),
               Contains("/materials/0/transfer: the transfer function point 2: value 0.5 is not "
                        "above the one before, 0.5"));
    CHECK_THAT(errorOf("[[0, 0], [1, -1]]"), Contains("/materials/0/transfer/1/1: expected"));
    CHECK_THAT(errorOf("[[0, 0.2], [1, 1]]"),
               Contains("/materials/0/transfer: the transfer function maps 0 to 0.2, and must map "
                        "it to 0"));
    CHECK_THAT(errorOf("[[0.1, 1], [1, 1]]"), Contains("maps 0 to 1, and must map it to 0"));
    CHECK_THAT(errorOf("[[0, 0], [1]]"), Contains("/materials/0/transfer/1: expected a point"));
    CHECK_THAT(errorOf("[[-1, 0], [1, 1]]", R"("gladstone_dale": 0.001, )"),
               Contains("a Gladstone–Dale material's field is a temperature"));
    std::string many = "[";
    for (int i = 0; i < 17; ++i) many += (i ? ", [" : "[") + std::to_string(i) + ", 0]";
    CHECK_THAT(errorOf(many + "]"),
               Contains("expected at most 16 elements in an array of 2 to 16 points"));
}
