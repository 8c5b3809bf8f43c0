#include <catch2/catch.hpp>

#include "core/field_registry.h"
#include "core/vdb_export.h"
#include "core/vdb_import.h"
#include "sim/smoke_publish.h"
#include "smoke_test_fields.h"
#include "support/test_paths.h"

using namespace eikon;
using namespace eikon::sim;

namespace {

MacGrid sampleState() {
    Domain d = test::closedBox({12, 10, 8}, 0.25f);
    d.origin = {-1.0f, 2.0f, 0.5f};
    MacGrid g(d);
    test::setDensityBump(g, glm::vec3(6.0f, 5.0f, 4.0f), 3.5f);
    for (std::size_t n = 0; n < g.temperature.count(); ++n) g.temperature[n] = 0.01f * float(n);
    g.velocity[0](12, 3, 2) = 1.5f;  // a +x face of the last cell: lives in voxel (12, 3, 2)
    g.velocity[1](4, 0, 6) = -2.0f;
    g.velocity[2](7, 8, 3) = 0.25f;
    g.velocity[0](7, 8, 3) = 0.75f;
    return g;
}

}  // namespace

TEST_CASE("publishing writes density, temperature and a staggered velocity in place",
          "[smoke][publish]") {
    const MacGrid g = sampleState();
    FieldRegistry reg;
    publishSmoke(g, reg, "smoke test");
    REQUIRE(reg.has("density"));
    REQUIRE(reg.has("temperature"));
    REQUIRE(reg.has("velocity"));
    CHECK(reg.get("density").isScalar());
    CHECK(reg.get("temperature").isScalar());
    CHECK(reg.get("velocity").isStaggered());

    const auto density = reg.floatGrid("density");
    CHECK(density->getConstAccessor().getValue(openvdb::Coord(6, 5, 4)) == g.density(6, 5, 4));
    CHECK(reg.floatGrid("temperature")->getConstAccessor().getValue(openvdb::Coord(3, 2, 1)) ==
          g.temperature(3, 2, 1));
    // Voxel (i, j, k)'s centre is the cell's centre: origin + (i + ½)·h.
    const openvdb::Vec3d w = density->transform().indexToWorld(openvdb::Coord(6, 5, 4));
    const glm::vec3 expected = g.domain.cellCenter(6, 5, 4);
    CHECK(w.x() == Approx(expected.x));
    CHECK(w.y() == Approx(expected.y));
    CHECK(w.z() == Approx(expected.z));
    // The active bounds are the cells holding density: within the domain box.
    const Bounds3 b = reg.get("density").activeWorldBounds();
    CHECK(b.min.x >= g.domain.origin.x - 1e-5f);
    CHECK(b.max.y <= g.domain.origin.y + 10 * 0.25f + 1e-5f);

    const auto vel = openvdb::gridConstPtrCast<openvdb::Vec3SGrid>(reg.get("velocity").grid);
    auto acc = vel->getConstAccessor();
    CHECK(acc.getValue(openvdb::Coord(12, 3, 2)) == openvdb::Vec3s(1.5f, 0.0f, 0.0f));
    CHECK(acc.getValue(openvdb::Coord(4, 0, 6)) == openvdb::Vec3s(0.0f, -2.0f, 0.0f));
    CHECK(acc.getValue(openvdb::Coord(7, 8, 3)) == openvdb::Vec3s(0.75f, 0.0f, 0.25f));
}

TEST_CASE("published smoke round-trips through core's VDB export and import", "[smoke][publish]") {
    const MacGrid g = sampleState();
    FieldRegistry reg;
    publishSmoke(g, reg, "smoke test");
    const std::string path = test::scratchDir("smoke_publish") + "/smoke.vdb";
    exportVdb(path, reg, {"density", "temperature", "velocity"});
    FieldRegistry back;
    importVdb(path, back);
    REQUIRE(back.has("density"));
    CHECK(back.get("velocity").isStaggered());
    auto acc = back.floatGrid("density")->getConstAccessor();
    const glm::ivec3 n = g.resolution();
    size_t differing = 0;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                if (acc.getValue(openvdb::Coord(i, j, k)) != g.density(i, j, k)) ++differing;
    CHECK(differing == 0);
    CHECK(back.floatGrid("density")->transform() == reg.floatGrid("density")->transform());
}

TEST_CASE("a published frame holds exactly what its cache file holds, the faint values too",
          "[smoke][publish]") {
    // Decaying smoke leaves values down to denormals; the cache drops those below
    // kExportPruneTolerance, and so does publishing, so that a frame rendered live and the same
    // frame rendered from `eikon simulate`'s cache (a farm's render) read the same fields.
    MacGrid g = sampleState();
    g.density(1, 1, 1) = 1.4e-45f;
    g.density(2, 1, 1) = -0.5f * kExportPruneTolerance;
    g.density(3, 1, 1) = kExportPruneTolerance;  // kept: the rule is "below"
    g.temperature(1, 2, 1) = 1e-9f;
    FieldRegistry live;
    publishSmoke(g, live, "smoke test");
    const std::string path = test::scratchDir("smoke_publish_faint") + "/smoke.vdb";
    exportVdb(path, live, {"density", "temperature", "velocity"});
    FieldRegistry cached;
    importVdb(path, cached);
    for (const char* name : {"density", "temperature"}) {
        const auto a = live.floatGrid(name);
        const auto b = cached.floatGrid(name);
        INFO(name);
        CHECK(a->activeVoxelCount() == b->activeVoxelCount());
        size_t differing = 0;
        for (auto v = a->cbeginValueOn(); v; ++v)
            differing += b->getConstAccessor().getValue(v.getCoord()) != *v ||
                         !b->getConstAccessor().isValueOn(v.getCoord());
        CHECK(differing == 0);
    }
    const auto density = live.floatGrid("density")->getConstAccessor();
    CHECK_FALSE(density.isValueOn(openvdb::Coord(1, 1, 1)));
    CHECK_FALSE(density.isValueOn(openvdb::Coord(2, 1, 1)));
    CHECK(density.getValue(openvdb::Coord(3, 1, 1)) == kExportPruneTolerance);
    CHECK_FALSE(
        live.floatGrid("temperature")->getConstAccessor().isValueOn(openvdb::Coord(1, 2, 1)));
}
