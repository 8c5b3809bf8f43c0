// `eikon bench soak`, short: the shipped soak scene simulated and rendered live on the GPU for
// 20 frames, sampled every 5: the CSV has a row per sample with every column filled, the GL
// objects alive do not change from sample to sample, the smoke keeps coming, and the summary
// with its verdict is printed. (The soak's memory is measured by the bench itself over 10,000
// frames, BENCHMARKS.md; a test judges no RSS, which moves with the machine.)
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::quoted;
using eikon::test::runEikon;
using eikon::test::scratchDir;
using eikon::test::sourcePath;

namespace {

const char* const kHeader =
    "frame,elapsed_s,ms_per_frame,rss_kib,hwm_kib,rss_anon_kib,heap_in_use_kib,gl_objects,"
    "gl_textures,gl_buffers,gl_programs,gl_queries,fields,density_total,image_mean";

std::vector<std::string> cells(const std::string& row) {
    std::vector<std::string> out;
    std::stringstream in(row);
    for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
    return out;
}

}  // namespace

TEST_CASE("eikon bench soak samples a live scene's memory and judges it", "[cli][bench][soak]") {
    const std::string dir = scratchDir("cli_bench_soak");
    const std::string csv = dir + "/soak.csv";
    const auto r = runEikon("bench soak " + quoted(sourcePath("data/scenes/soak_smoke.json")) +
                                " --frames 20 --every 5 --warmup 10 --csv " + quoted(csv),
                            dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);

    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    CHECK(header == kHeader);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) rows.push_back(cells(line));
    // Frame 1 (the start-up), every fifth, the warm-up's (10) among them.
    REQUIRE(rows.size() == 5);
    const int frames[] = {1, 5, 10, 15, 20};
    double density = 0.0;
    for (size_t i = 0; i < rows.size(); ++i) {
        INFO("row " << i);
        REQUIRE(rows[i].size() == 15);
        CHECK(std::stoi(rows[i][0]) == frames[i]);
        CHECK(std::stod(rows[i][2]) > 0.0);                       // ms per frame
        CHECK(std::stoll(rows[i][3]) > 0);                        // VmRSS
        CHECK(std::stoll(rows[i][4]) >= std::stoll(rows[i][3]));  // VmHWM is the peak
        CHECK(std::stoll(rows[i][6]) > 0);                        // heap in use
        CHECK(std::stoi(rows[i][7]) > 0);         // GL objects: the GPU backend renders
        CHECK(rows[i][7] == rows[0][7]);          // none made per frame and left alive
        CHECK(std::stoi(rows[i][12]) == 3);       // density, temperature, velocity
        CHECK(std::stod(rows[i][13]) > density);  // the source keeps emitting
        density = std::stod(rows[i][13]);
        CHECK(std::stod(rows[i][14]) > 0.0);  // the picture is lit
    }

    CHECK(r.out.find("# soak: 20 frames in ") != std::string::npos);
    CHECK(r.out.find("# ms/frame by stage: simulate ") != std::string::npos);
    CHECK(r.out.find("# RSS after the warm-up (frame 10): ") != std::string::npos);
    CHECK(r.out.find("# growth after the warm-up: max ") != std::string::npos);
    CHECK(r.out.find("# GL objects alive: ") != std::string::npos);
    CHECK(r.out.find("# verdict: PASS") != std::string::npos);
}

TEST_CASE("eikon bench soak refuses bad settings in one line", "[cli][bench][soak]") {
    const std::string dir = scratchDir("cli_bench_soak_errors");
    eikon::test::checkOneLineError(runEikon("bench soak --frames 0", dir), "--frames: ");
    eikon::test::checkOneLineError(runEikon("bench soak --every 0", dir), "--every: ");
    eikon::test::checkOneLineError(runEikon("bench soak " + quoted(dir + "/none.json"), dir),
                                   dir + "/none.json");
}
