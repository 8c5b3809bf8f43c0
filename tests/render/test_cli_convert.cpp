// `eikon convert`: a scan written as a VDB file that OpenVDB reads back voxel for voxel, and that
// renders as the scene's scan source renders it; its errors keep every file as it was.
#include <catch2/catch.hpp>

#include <filesystem>

#include "core/field_registry.h"
#include "core/scan_volume.h"
#include "core/vdb_import.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::contains;
using eikon::test::quoted;
using eikon::test::runEikon;

namespace {

const std::string kTooth = "volumes/tooth_103x94x161_uint8.raw";

}  // namespace

TEST_CASE("eikon convert writes a scan as a VDB fog volume, voxel for voxel", "[cli][scan]") {
    const std::string dir = eikon::test::scratchDir("cli_convert");
    const std::string tooth = eikon::test::sharedData(kTooth);
    const std::string out = dir + "/tooth.vdb";
    const auto r = runEikon("convert " + quoted(tooth) + " " + quoted(out) +
                                " --window 100 240 --spacing 0.0125 0.0125 0.0125 --field density",
                            dir);
    INFO(r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(contains(r.out, "wrote " + out + " (grid 'density', "));
    CHECK(contains(r.err, "103×94×161 uint8, values 0 … 255, into field 'density'"));

    eikon::FieldRegistry fields;
    eikon::importVdb(out, fields);
    const auto written = fields.floatGrid("density");
    eikon::ScanFileOptions options;
    options.spacing = glm::dvec3(0.0125);
    options.read.window = eikon::ScanWindow{100.0, 240.0};
    const auto scan = eikon::readScanFile(tooth, options).volume.grid;
    CHECK(written->activeVoxelCount() == scan->activeVoxelCount());
    CHECK(written->voxelSize().x() == Approx(0.0125));
    const auto acc = written->getConstAccessor();
    for (auto it = scan->cbeginValueOn(); it; ++it) REQUIRE(acc.getValue(it.getCoord()) == *it);

    // Not over an existing file, and never over the scan itself; the file stays as it was.
    const std::string before = eikon::test::readFile(out);
    const auto again = runEikon("convert " + quoted(tooth) + " " + quoted(out), dir);
    CHECK(again.exitCode == 1);
    CHECK(again.err == "eikon: " + out + ": exists; give another file or --overwrite\n");
    CHECK(eikon::test::readFile(out) == before);
    const auto self = runEikon("convert " + quoted(out) + " " + quoted(out) + " --overwrite", dir);
    CHECK(self.err ==
          "eikon: " + out + ": is the scan being converted; give another output file\n");
    CHECK(eikon::test::readFile(out) == before);
}

TEST_CASE("eikon convert: bad scans and options get one line and write nothing", "[cli][scan]") {
    const std::string dir = eikon::test::scratchDir("cli_convert_errors");
    const std::string out = dir + "/out.vdb";
    const std::string tooth = eikon::test::sharedData(kTooth);
    // A truncated copy of the tooth, named as the whole.
    const std::string cut = dir + "/tooth_103x94x161_uint8.raw";
    eikon::test::writeFile(cut, eikon::test::readFile(tooth).substr(0, 100000));
    struct Case {
        std::string args;
        std::string error;
    };
    const Case cases[] = {
        {quoted(cut) + " " + quoted(out),
         cut + ": holds 100000 bytes of samples, and 103×94×161 uint8 is 1558802 bytes: the file "
               "is truncated, or its dimensions or value type do not match the file"},
        {quoted(tooth) + " " + quoted(out) + " --type uint12",
         "--type: expected uint8, int8, uint16, int16, uint32, int32, uint64, int64, float32 or "
         "float64, got \"uint12\""},
        {quoted(tooth) + " " + quoted(out) + " --window 5 5", "--window: expected LOW HIGH"},
        {quoted(tooth) + " " + quoted(out) + " --field velocity", "--field: expected a scalar"},
        {quoted(dir + "/none.raw") + " " + quoted(out),
         dir + "/none.raw: a raw file needs its dimensions"},
    };
    for (const Case& c : cases) {
        const auto r = runEikon("convert " + c.args, dir);
        INFO(c.args << "\n" << r.err);
        CHECK(r.exitCode == 1);
        CHECK(contains(r.err, "eikon: " + c.error));
        CHECK(r.err.find('\n') == r.err.size() - 1);
        CHECK_FALSE(std::filesystem::exists(out));
    }
}

TEST_CASE("eikon info on a scan: layout, values, percentiles and a histogram", "[cli][scan]") {
    const std::string dir = eikon::test::scratchDir("cli_info_scan");
    const std::string tooth = eikon::test::sharedData(kTooth);
    const auto r = runEikon("info " + quoted(tooth), dir);
    INFO(r.out << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(contains(r.out, tooth + ": scanned volume, 103×94×161 uint8, raw file\n"));
    CHECK(contains(r.out, "  spacing 1 1 1, origin 0 0 0, last sample at 102 93 160\n"));
    // numpy: 15 zeros among the 1,558,802 samples, none below 0 or above 255, the median 79.
    CHECK(contains(r.out, "  values 0 … 255; 15 of 1558802 samples are 0 (0.000962277 %)\n"));
    CHECK(contains(r.out, ", 50 % 79, "));
    CHECK(contains(r.out, "  histogram (16 bins from 0 to 255):\n"));
    // numpy's bincount over [64, 80): 802,740 samples, the background, the tallest bar.
    CHECK(contains(r.out,
                   "    [     63.75,      79.69)     802740  ####################"
                   "####################\n"));
    const auto bad = runEikon("info " + quoted(dir + "/x_4x4x4_uint8.raw"), dir);
    CHECK(bad.exitCode == 1);
    CHECK(contains(bad.err, "x_4x4x4_uint8.raw: no such file"));
}
