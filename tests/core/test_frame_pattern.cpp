#include <catch2/catch.hpp>

#include "core/error.h"
#include "core/frame_pattern.h"

using namespace eikon;

TEST_CASE("frame tokens of Blender, printf and Houdini read as one run of #", "[frames]") {
    CHECK(toHashPattern("fluid_data_####.vdb", "w") == "fluid_data_####.vdb");
    CHECK(toHashPattern("fluid_data_%04d.vdb", "w") == "fluid_data_####.vdb");
    CHECK(toHashPattern("fluid_data_%d.vdb", "w") == "fluid_data_#.vdb");
    CHECK(toHashPattern("pyro.$F4.vdb", "w") == "pyro.####.vdb");
    CHECK(toHashPattern("pyro.$F.vdb", "w") == "pyro.#.vdb");
    CHECK(toHashPattern("shot_######.png", "w") == "shot_######.png");
    // No token: unchanged, including Houdini's other variables and a lone %.
    CHECK(toHashPattern("smoke.vdb", "w") == "smoke.vdb");
    CHECK(toHashPattern("$FPS_$FF_100%.vdb", "w") == "$FPS_$FF_100%.vdb");
    CHECK_FALSE(hasHashRun("smoke_0001.vdb"));
    CHECK(hasHashRun(toHashPattern("smoke_$F3.vdb", "w")));
}

TEST_CASE("a name with two frame tokens or an unusable printf token is refused",
          "[frames][bad-input]") {
    CHECK_THROWS_WITH(toHashPattern("a_####_%04d.vdb", "-o"),
                      Catch::StartsWith("-o: ") && Catch::Contains("two frame-number tokens"));
    CHECK_THROWS_WITH(toHashPattern("a_$F4_##.png", "x"), Catch::Contains("two frame-number"));
    CHECK_THROWS_WITH(toHashPattern("a_%4d.png", "x"), Catch::Contains("pads with spaces"));
    CHECK_THROWS_WITH(toHashPattern("a_%0d.png", "x"), Catch::Contains("no width"));
    CHECK_THROWS_WITH(toHashPattern("a_$F0.png", "x"), Catch::Contains("no width"));
    CHECK_THROWS_WITH(toHashPattern("a_%012d.png", "x"), Catch::Contains("outside 1 to 9"));
    CHECK_THROWS_WITH(toHashPattern("a_%099999999999999d.png", "x"),
                      Catch::Contains("outside 1 to 9"));
}

TEST_CASE("a # run expands to the frame, zero padded to its width", "[frames]") {
    CHECK(expandHashPattern("shot_####.png", 7) == "shot_0007.png");
    CHECK(expandHashPattern("shot_##.png", 1234) == "shot_1234.png");  // wider: written whole
    CHECK(expandHashPattern("shot_#.png", 0) == "shot_0.png");
    CHECK(expandHashPattern("still.png", 5) == "still.png");
}
