#include <catch2/catch.hpp>

#include <fstream>

#include "core/error.h"
#include "core/field_registry.h"
#include "core/log.h"
#include "core/scene.h"
#include "core/scene_sources.h"
#include "core/vdb_sequence.h"
#include "support/test_paths.h"

using namespace eikon;

TEST_CASE("the Blender sequence is found with its gap listed", "[sequence]") {
    const VdbSequence seq =
        findVdbSequence(test::sharedData("vdb/blender_smoke_c42/fluid_data_0002.vdb"));
    CHECK(seq.prefix == "fluid_data_");
    CHECK(seq.digits == 4);
    CHECK(seq.frames.size() == 3);
    CHECK(seq.first() == 1);
    CHECK(seq.last() == 10);
    CHECK(seq.missing == std::vector<int>{3, 4, 5, 6, 7, 8, 9});
    CHECK(seq.missingText() == "3-9");
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

TEST_CASE("printf's %04d and Houdini's $F4 find the same frames as ####", "[sequence]") {
    const std::string dir = test::sharedData("vdb/blender_smoke_c42/");
    const auto frames = findVdbSequence(dir + "fluid_data_####.vdb").frames;
    CHECK(findVdbSequence(dir + "fluid_data_%04d.vdb").frames == frames);
    CHECK(findVdbSequence(dir + "fluid_data_$F4.vdb").frames == frames);
    CHECK(findVdbSequence(dir + "fluid_data_%d.vdb").frames == frames);  // width is not a filter
    CHECK(findVdbSequence(dir + "fluid_data_$F4.vdb").pattern() ==
          findVdbSequence(dir + "fluid_data_####.vdb").pattern());
    CHECK_THROWS_WITH(findVdbSequence(dir + "fluid_####_data.vdb"),
                      Catch::Contains("the frame number right before the extension"));
    CHECK_THROWS_WITH(findVdbSequence(dir + "fluid##_####.vdb"),
                      Catch::Contains("two frame-number tokens"));
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

TEST_CASE("a rendered frame missing from a sequence is an error unless the scene holds frames",
          "[sequence][bad-input]") {
    Scene scene;
    scene.path = "gap.json";
    SourceSpec source;
    source.type = SourceType::VdbSequence;
    source.file = test::sharedData("vdb/blender_smoke_c42/fluid_data_####.vdb");
    source.jsonPath = "/sources/0";
    scene.sources.push_back(source);
    FieldRegistry fields;
    SECTION("the default: an error naming the source, the frame and the gaps") {
        ScopedWarningCapture warnings;
        SceneSources sources(scene);
        sources.loadFrame(2, fields);  // present
        CHECK(fields.has("density"));
        CHECK_THROWS_WITH(
            sources.loadFrame(5, fields),
            Catch::StartsWith("gap.json:/sources/0: ") &&
                Catch::Contains("fluid_data_####.vdb has frames 1-2, 10; 5 missing between") &&
                Catch::Contains("\"missing_frames\": \"hold\"") && Catch::Contains("--hold"));
        sources.loadFrame(10, fields);  // present again
        // Outside the sequence: an error too (it was clamped to the last frame silently).
        CHECK_THROWS_WITH(sources.loadFrame(12, fields),
                          Catch::Contains("has frames 1-2, 10; 12 outside them"));
        CHECK_THROWS_WITH(sources.loadFrame(0, fields), Catch::Contains("0 outside them"));
        CHECK_FALSE(warnings.contains("missing"));  // no warning of gaps before the error line
    }
    SECTION("checked up front: every absent frame of a list in one line") {
        CHECK_NOTHROW(checkSequenceFrames(scene, {1, 2, 10}));
        CHECK_THROWS_WITH(
            checkSequenceFrames(scene, {1, 2, 3, 4, 9, 10, 11, 12}),
            Catch::EndsWith("fluid_data_####.vdb has frames 1-2, 10; 11-12 outside them; "
                            "3-4, 9 missing between; write them, render the frames it has, or "
                            "hold the nearest frame (\"missing_frames\": \"hold\" in a scene, "
                            "--hold on the command line)"));
    }
    SECTION("\"hold\": the nearest earlier frame, the gaps said once") {
        scene.sources[0].holdMissingFrames = true;
        ScopedWarningCapture warnings;
        SceneSources sources(scene);
        sources.loadFrame(5, fields);
        CHECK(fields.get("density").origin.find("fluid_data_0002.vdb") != std::string::npos);
        int gapWarnings = 0;
        for (const std::string& w : warnings.warnings())
            gapWarnings += w.find("missing") != std::string::npos;
        CHECK(gapWarnings == 1);
        CHECK(warnings.contains("fluid_data_####.vdb: frames 3-9 are missing"));
        // The end frames stand in beyond the ends.
        sources.loadFrame(12, fields);
        CHECK(fields.get("density").origin.find("fluid_data_0010.vdb") != std::string::npos);
        sources.loadFrame(0, fields);
        CHECK(fields.get("density").origin.find("fluid_data_0001.vdb") != std::string::npos);
        CHECK_NOTHROW(checkSequenceFrames(scene, {0, 5, 99}));
    }
}
