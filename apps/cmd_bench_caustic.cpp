// `eikon bench caustic`: the floor caustic of a glass ball, set up as POV-Ray's focus sweep in
// ../shared/peers/povray_caustic.pov (TOPVIEW): a sphere of radius 1 and n = 1.5 whose centre is
// D above a diffuse floor at y = 0, a point light 100 above the floor on the sphere's axis. For
// each D the photons (CPU twin) fill the floor's receiver map over the 2.4 × 2.4 square under the
// sphere; each map is written as raw float32 irradiance (green channel, row-major, texels of
// size 2.4 / width) for scripts/compare_caustic.py, which measures peak and r50 as the peer's
// povray_caustic_focus.py does and sets them beside POV-Ray's and an exact Snell trace's.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/bench_report.h"
#include "apps/commands.h"
#include "core/error.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/transport/photons/photon_transport.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct BenchCausticOptions {
    std::string distances = "1.2,1.4,1.6,1.8,2,2.5,3";
    int resolution = 96;  // voxels across the 2.4-unit square
    int perSide = 512;
    float falloff = 0.0f;
    std::string edgeFilter = "bspline";  // the sphere's default
    int threads = 0;
    bool quick = false;
    std::string out = "out/bench/caustic";
};

constexpr double kHalf = 1.2;  // the floor square is [-1.2, 1.2]², as POV-Ray's TOPVIEW

// The scene at centre height d, as JSON (the scene format's own reader checks it).
std::string sceneJson(double d, const BenchCausticOptions& o) {
    const double h = 2.0 * kHalf / o.resolution;
    std::ostringstream s;
    s.precision(9);
    // The volume's floor lies two voxels below y = 0, so that the receiver at y = 0 is inside it;
    // its top a few voxels above the sphere. Cubic voxels of h.
    const int ny = int(std::ceil((d + 1.0 + 6.0 * h) / h));
    s << R"({"volume": {"bounds": {"min": [)" << -kHalf << ", " << -2.0 * h << ", " << -kHalf
      << R"(], "max": [)" << kHalf << ", " << (ny - 2) * h << ", " << kHalf
      << R"(]}, "resolution": [)" << o.resolution << ", " << ny << ", " << o.resolution << R"(]},
 "sources": [{"type": "sphere", "field": "n", "center": [0, )"
      << d << R"(, 0], "radius": 1, "value": 1, "falloff": )" << o.falloff
      << R"(, "edge_filter": ")" << o.edgeFilter << R"(", "voxel_size": )" << h << R"(}],
 "materials": [{"name": "glass", "field": "n", "ior": 1.5}],
 "lights": [{"type": "point", "position": [0, 100, 0], "intensity": 1}],
 "receivers": [{"type": "plane", "axis": "y", "position": 0, "albedo": [1, 1, 1]}],
 "camera": {"position": [0, 4, -4], "look_at": [0, 0, 0]},
 "render": {"width": 4, "height": 4, "light_transport": {"method": "photons",
   "photons": {"per_side": )"
      << o.perSide << R"(}}}})";
    return s.str();
}

int runBenchCaustic(BenchCausticOptions o) {
    if (o.quick) {
        o.distances = "1.5";
        o.resolution = 48;
        o.perSide = 128;
    }
    if (o.resolution < 16 || o.resolution > 256)
        throw Error("--resolution", "expected 16 to 256 voxels across the floor square");
    if (o.perSide < 16 || o.perSide > 4096) throw Error("--per-side", "expected 16 to 4096");
    if (!(o.falloff >= 0.0f)) throw Error("--falloff", "expected a number >= 0");
    if (o.edgeFilter != "box" && o.edgeFilter != "bspline")
        throw Error("--edge-filter", "expected box or bspline, got '" + o.edgeFilter + "'");
    std::vector<double> distances;
    for (const std::string& item : splitList(o.distances)) {
        char* end = nullptr;
        const double d = std::strtod(item.c_str(), &end);
        if (end == item.c_str() || *end != '\0' || !(d > 1.0) || d > 10.0)
            throw Error("--distances", "expected centre heights in (1, 10], got '" + item + "'");
        distances.push_back(d);
    }
    const auto threadCap = limitThreads(o.threads);
    fs::create_directories(o.out);

    std::printf("# eikon bench caustic: a glass ball's floor caustic, as POV-Ray's focus sweep\n");
    printBenchHeader(stdout, o.threads);
    std::printf(
        "# sphere R 1, n 1.5, falloff %g, edge filter %s, centre D above the floor; point light "
        "at 100; %d voxels across the 2.4-unit floor square; %d^2 photons; CPU twin\n",
        double(o.falloff), o.edgeFilter.c_str(), o.resolution, o.perSide);
    std::printf("%-6s | %9s | %7s %7s | %s\n", "D", "ms", "width", "height", "map");
    for (const double d : distances) {
        char name[64];
        std::snprintf(name, sizeof name, "caustic_D%.3g", d);
        const std::string scenePath = o.out + "/" + name + ".json";
        std::ofstream(scenePath) << sceneJson(d, o);
        const Scene scene = loadScene(scenePath);
        const auto t0 = std::chrono::steady_clock::now();
        FrameRenderer renderer(scene, Backend::Cpu);
        renderer.render(0);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        const auto* photons = dynamic_cast<const PhotonTransport*>(&renderer.lightTransport());
        if (!photons) throw Error(scenePath, "the scene traced no photons");
        const std::vector<glm::vec4> map = photons->volumes().receiverMap;
        // A y-normal receiver's map runs along z (texels.x, fastest), then x (receiver_map.h).
        const int width = 2 * o.resolution;  // texels_per_voxel 2
        if (map.size() != size_t(width) * size_t(width))
            throw Error(scenePath, "unexpected receiver map size " + std::to_string(map.size()));
        const std::string mapPath = o.out + "/" + name + ".f32";
        std::ofstream file(mapPath, std::ios::binary);
        for (const glm::vec4& t : map)
            file.write(reinterpret_cast<const char*>(&t.y), sizeof(float));
        if (!file) throw Error(mapPath, "cannot write the map");
        std::printf("%-6.3g | %9.1f | %7d %7d | %s\n", d, ms, width, width, mapPath.c_str());
        std::fflush(stdout);
    }
    std::printf(
        "# compare: /usr/bin/python3 scripts/compare_caustic.py --eikon %s [--povray "
        "DIR]\n",
        o.out.c_str());
    return 0;
}

}  // namespace

void addBenchCausticCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "caustic", "A glass ball's floor caustic at several heights, as POV-Ray's focus sweep");
    auto o = std::make_shared<BenchCausticOptions>();
    cmd->add_option("--distances", o->distances,
                    "comma-separated centre heights D, in radii (default 1.2,...,3)");
    cmd->add_option("--resolution", o->resolution,
                    "voxels across the 2.4-unit floor square (default 96)");
    cmd->add_option("--per-side", o->perSide, "photons per side of the light's grid (default 512)");
    cmd->add_option("--falloff", o->falloff,
                    "the sphere's falloff, scene units (default 0: sharp)");
    cmd->add_option("--edge-filter", o->edgeFilter,
                    "the sphere's edge filter, box or bspline (default bspline, a sphere's)");
    cmd->add_option("--threads", o->threads, "cap TBB's threads (default: all cores)");
    cmd->add_flag("--quick", o->quick, "a small run, to check that it works: D 1.5, 48 voxels");
    cmd->add_option("--out", o->out, "folder for the maps (default out/bench/caustic)");
    cmd->callback([o, &exitCode] { exitCode = runBenchCaustic(*o); });
}

}  // namespace eikon::app
