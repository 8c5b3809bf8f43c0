// `eikon bench methods --quick`: every registered light-transport method at every named setting
// on every analytic case, with errors that agree with what each method models: photons follow the
// closed forms of bent light and keep their energy account, straight light volumes are exact
// under Beer–Lambert and show no focus. The suite is measured against closed forms here, so a
// broken measurement (or method) fails, not just a broken table.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "render/light_transport_registry.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::quoted;
using eikon::test::runEikon;
using eikon::test::scratchDir;

namespace {

// (case, method, setting) -> error, from the bench's TSV.
std::map<std::string, double> readErrors(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    REQUIRE(line == "case\tmethod\tsetting\tresolution\tms\terror\terror_unit\tsteps");
    std::map<std::string, double> errors;
    while (std::getline(in, line)) {
        std::stringstream row(line);
        std::string c, method, setting, resolution, ms, error;
        std::getline(row, c, '\t');
        std::getline(row, method, '\t');
        std::getline(row, setting, '\t');
        std::getline(row, resolution, '\t');
        std::getline(row, ms, '\t');
        std::getline(row, error, '\t');
        CHECK(std::stod(ms) > 0.0);
        errors[c + " " + method + " " + setting] = std::stod(error);  // "nan" reads as NaN
    }
    return errors;
}

}  // namespace

TEST_CASE("eikon bench methods --quick measures every method against the closed forms",
          "[cli][bench][light_transport]") {
    const std::string dir = scratchDir("cli_bench_methods");
    const std::string tsv = dir + "/methods.tsv";
    const auto r = runEikon("bench methods --quick --tsv " + quoted(tsv), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    const std::map<std::string, double> e = readErrors(tsv);

    // Every registered method, every named setting, every case: a method added later is here.
    for (const eikon::LightTransportMethod& m : eikon::lightTransportMethods())
        for (const auto& [setting, json] : m.benchSettings)
            for (const char* c : {"slab", "ball_lens", "luneburg", "linear_n2", "energy"}) {
                INFO(c << " " << m.name << " " << setting);
                CHECK(e.count(std::string(c) + " " + m.name + " " + setting) == 1);
            }

    for (const char* setting : {"coarse", "default", "fine"}) {
        INFO(setting);
        const std::string s = std::string(" ") + setting;
        // Straight light volumes: exact transmittance in a homogeneous slab (float rounding),
        // no focus behind either lens, the straight beam misses the parabola's exit point by
        // its whole deflection (0.17 units, 4.2 voxels at 49³), no energy account.
        CHECK(e.at("slab light_volumes" + s) < 1e-4);
        CHECK(std::isnan(e.at("ball_lens light_volumes" + s)));
        CHECK(std::isnan(e.at("luneburg light_volumes" + s)));
        CHECK(e.at("linear_n2 light_volumes" + s) > 3.0);
        CHECK(std::isnan(e.at("energy light_volumes" + s)));
        // Photons: foci and the bent exit point within 1.5 voxels (the smoothing's reach; 0.12 to
        // 0.65 measured), the energy balanced to rounding (1e-9), and Beer–Lambert within the
        // smoothing's bias of an exponential, cosh²(κh/2), the boundary voxels the smoothing
        // reaches past, and the photon grid's sampling of each voxel (4.0 to 6.3 % measured at
        // 49³: the tolerance is twice the worst).
        CHECK(e.at("ball_lens photons" + s) < 1.5);
        CHECK(e.at("luneburg photons" + s) < 1.5);
        CHECK(e.at("linear_n2 photons" + s) < 1.5);
        CHECK(e.at("energy photons" + s) < 1e-6);
        CHECK(e.at("slab photons" + s) < 0.13);
    }
}
