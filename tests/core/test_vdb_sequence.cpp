#include <catch2/catch.hpp>

#include <fstream>

#include "core/error.h"
#include "core/log.h"
#include "core/vdb_sequence.h"
#include "support/test_paths.h"

using namespace eikon;

TEST_CASE("the Blender sequence is found with its gap reported", "[sequence]") {
    ScopedWarningCapture warnings;
    const VdbSequence seq =
        findVdbSequence(test::sharedData("vdb/blender_smoke_c42/fluid_data_0002.vdb"));
    CHECK(seq.prefix == "fluid_data_");
    CHECK(seq.digits == 4);
    CHECK(seq.frames.size() == 3);
    CHECK(seq.first() == 1);
    CHECK(seq.last() == 10);
    CHECK(seq.missing == std::vector<int>{3, 4, 5, 6, 7, 8, 9});
    CHECK(warnings.contains("fluid_data_####.vdb: frames 3-9 are missing"));
    // A missing frame shows the nearest earlier one; before the first, the first.
    CHECK(seq.fileForFrame(5).find("fluid_data_0002.vdb") != std::string::npos);
    CHECK(seq.fileForFrame(10).find("fluid_data_0010.vdb") != std::string::npos);
    CHECK(seq.fileForFrame(0).find("fluid_data_0001.vdb") != std::string::npos);
    CHECK(seq.fileForFrame(99).find("fluid_data_0010.vdb") != std::string::npos);
    // The pattern form finds the same frames.
    const VdbSequence byPattern =
        findVdbSequence(test::sharedData("vdb/blender_smoke_c42/fluid_data_####.vdb"));
    CHECK(byPattern.frames == seq.frames);
}

TEST_CASE("the three naming styles are recognised and kept apart", "[sequence]") {
    const std::string dir = test::scratchDir("sequence_styles");
    for (const char* name : {"smoke_0001.vdb", "smoke_0002.vdb", "smoke.0001.vdb", "smoke.0003.vdb",
                             "smoke0007.vdb", "smoke0008.vdb", "smoke0009.vdb", "other_0001.vdb"})
        std::ofstream(dir + "/" + name) << "x";
    CHECK(findVdbSequence(dir + "/smoke_0001.vdb").frames.size() == 2);
    const VdbSequence dotted = findVdbSequence(dir + "/smoke.####.vdb");
    CHECK(dotted.frames.size() == 2);
    CHECK(dotted.missing == std::vector<int>{2});
    const VdbSequence plain = findVdbSequence(dir + "/smoke0008.vdb");
    CHECK(plain.first() == 7);
    CHECK(plain.last() == 9);
    CHECK(plain.missing.empty());
}

TEST_CASE("no frames or no number is a clear error", "[sequence][bad-input]") {
    const std::string dir = test::scratchDir("sequence_errors");
    CHECK_THROWS_WITH(findVdbSequence(dir + "/nothing_####.vdb"),
                      Catch::Contains("no frames of") && Catch::Contains("nothing_####.vdb"));
    CHECK_THROWS_WITH(findVdbSequence(dir + "/smoke.vdb"),
                      Catch::Contains("not a frame of a sequence"));
    CHECK_THROWS_WITH(findVdbSequence(dir + "/absent/smoke_0001.vdb"),
                      Catch::Contains("does not exist"));
}
