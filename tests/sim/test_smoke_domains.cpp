// Several smoke domains in one scene, stepped live (sim/field_simulation.h): each domain is a
// solver of its own that publishes labelled fields, and none disturbs another, so a domain's
// smoke in a scene of two is, voxel for voxel, its smoke in a scene of its own.
#include <catch2/catch.hpp>

#include <openvdb/openvdb.h>

#include "core/field_registry.h"
#include "core/scene.h"
#include "sim/field_simulation.h"

using namespace eikon;

namespace {

// One domain's JSON: a unit box at x0 with a buoyant puff near its floor. Cells of 1/8 and offsets
// of halves keep every cell centre exact in floats, so a domain moved along x is the same smoke.
std::string domainJson(const std::string& label, float x0) {
    const std::string x = std::to_string(x0), x1 = std::to_string(x0 + 1.0f);
    return R"({"label": ")" + label + R"(", "domain": {"min": [)" + x + R"(, 0, 0], "max": [)" +
           x1 +
           R"(, 1, 1]}, "resolution": 8,
               "sources": [{"type": "sphere", "center": [)" +
           std::to_string(x0 + 0.5f) +
           R"(, 0.2, 0.5], "radius": 0.2, "density_rate": 3, "temperature_rate": 10}]})";
}

std::string sceneJson(const std::string& simulation, const std::string& materials,
                      const std::string& extra = "") {
    return R"({"sources": [{"type": "simulation"}], "materials": [)" + materials +
           R"(], "time": {"fps": 12, "frame_start": 1, "frame_end": 4}, "simulation": )" +
           simulation + extra + "}";
}

// Every active voxel of `a` holds the same value in `b` and the other way round, with the same
// voxel-to-world transform up to `shift` along x.
void checkSameGrid(const Field& a, const Field& b, double shift) {
    const auto ga = openvdb::gridPtrCast<openvdb::FloatGrid>(a.grid);
    const auto gb = openvdb::gridPtrCast<openvdb::FloatGrid>(b.grid);
    REQUIRE(ga);
    REQUIRE(gb);
    CHECK(ga->activeVoxelCount() == gb->activeVoxelCount());
    CHECK(ga->activeVoxelCount() > 0);
    const openvdb::Vec3d offset = gb->transform().indexToWorld(openvdb::Vec3d(0)) -
                                  ga->transform().indexToWorld(openvdb::Vec3d(0));
    CHECK(offset.x() == Approx(shift).margin(1e-6));
    CHECK(offset.y() == 0.0);
    CHECK(offset.z() == 0.0);
    auto accB = gb->getConstAccessor();
    int differ = 0;
    for (auto it = ga->cbeginValueOn(); it; ++it)
        if (accB.getValue(it.getCoord()) != *it) ++differ;
    CHECK(differ == 0);
}

}  // namespace

TEST_CASE("two smoke domains step apart and publish labelled fields", "[smoke][simulation]") {
    const Scene two = parseScene(
        sceneJson(
            "[" + domainJson("left", 0.0f) + ", " + domainJson("right", 1.5f) + "]",
            R"({"name": "a", "field": "density.left"}, {"name": "b", "field": "density.right"})"),
        "two.json");
    Scene alone =
        parseScene(sceneJson(domainJson("left", 0.0f), R"({"name": "a", "field": "density.left"})"),
                   "one.json");

    auto twoSims = sim::makeFieldSimulations(two);
    auto oneSim = sim::makeFieldSimulations(alone);
    REQUIRE(twoSims.size() == 2);
    REQUIRE(oneSim.size() == 1);
    FieldRegistry fields, reference;
    for (auto& s : twoSims) {
        CHECK(s->advanceToFrame(3));
        s->publish(fields, "two.json: simulation frame 3");
    }
    oneSim[0]->advanceToFrame(3);
    oneSim[0]->publish(reference, "one.json: simulation frame 3");

    const std::vector<std::string> names = fields.names();
    CHECK(names == std::vector<std::string>{"density.left", "density.right", "temperature.left",
                                            "temperature.right", "velocity.left",
                                            "velocity.right"});
    CHECK(fields.get("density.right").origin ==
          "two.json: simulation frame 3 (/simulation/1):density");
    // The left domain is its lone self; the right one, the same set-up 1.5 further along x, is
    // the left one moved there.
    checkSameGrid(reference.get("density.left"), fields.get("density.left"), 0.0);
    checkSameGrid(fields.get("density.left"), fields.get("density.right"), 1.5);
    checkSameGrid(fields.get("temperature.left"), fields.get("temperature.right"), 1.5);

    SECTION("a track moves one domain's source only") {
        const Scene keyed = parseScene(
            sceneJson(
                "[" + domainJson("left", 0.0f) + ", " + domainJson("right", 1.5f) + "]",
                R"({"name": "a", "field": "density.left"}, {"name": "b", "field": "density.right"})",
                R"(, "animation": [{"target": "/simulation/1/sources/0/center",
                                          "times": [0, 0.3], "values": [[2, 0.2, 0.5], [2.3, 0.2, 0.5]]}])"),
            "keyed.json");
        auto sims = sim::makeFieldSimulations(keyed);
        REQUIRE(sims.size() == 2);
        FieldRegistry moved;
        for (auto& s : sims) {
            s->advanceToFrame(3);
            s->publish(moved, "keyed.json");
        }
        checkSameGrid(fields.get("density.left"), moved.get("density.left"), 0.0);
        const auto still =
            openvdb::gridPtrCast<openvdb::FloatGrid>(fields.get("density.right").grid);
        const auto pushed =
            openvdb::gridPtrCast<openvdb::FloatGrid>(moved.get("density.right").grid);
        // The moving source leaves its smoke further along +x: the density's centroid moved.
        auto centroidX = [](const openvdb::FloatGrid& g) {
            double sum = 0.0, weighted = 0.0;
            for (auto it = g.cbeginValueOn(); it; ++it) {
                sum += *it;
                weighted += *it * g.transform().indexToWorld(it.getCoord()).x();
            }
            return weighted / sum;
        };
        CHECK(centroidX(*pushed) > centroidX(*still) + 0.05);
    }
}
