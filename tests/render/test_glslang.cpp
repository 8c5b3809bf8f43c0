// Every shader Eikon compiles, in every define combination it compiles it with, through glslang,
// the Khronos reference compiler (glslangValidator, Debian's glslang-tools): Mesa accepts things
// that other drivers reject, and llvmpipe is the only driver the tests otherwise see. The list of
// variants is written out here; the test fails when a shader file or an `#ifdef` switch of the
// shaders is in none of them, so that a new one cannot go unchecked.
#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "render/shader_program.h"
#include "support/test_paths.h"

namespace fs = std::filesystem;

namespace {

struct Variant {
    std::string file;  // relative to the shaders folder
    std::vector<std::string> defines;
};

// What the renderer builds (render/*_gpu.cpp, render/transport/*/…_gpu.cpp) and the GL tests'
// own shaders, in every combination of their switches.
std::vector<Variant> variants() {
    std::vector<Variant> list;
    const std::vector<std::string> none;
    for (const char* file :
         {"refraction_gradient.comp", "octree_minmax.comp", "octree_label.comp",
          "smooth_volume.comp", "photon_resolve.comp", "photon_round.comp", "voxelize_toggle.comp",
          "voxelize_scan.comp", "voxelize_coverage.comp", "gaussian_blur.comp", "display.vert",
          "display.frag", "test/gid_double.comp", "test/photons_compile.comp",
          "test/std430_view_params.comp", "test/std430_particles.comp",
          "test/wavefront_compile.comp"})
        list.push_back({file, none});
    // View: texture-unit filtering (EK_HARDWARE_TRILINEAR) × one channel a dispatch (dispersion)
    // × the lights' highlights (EK_SPECULAR).
    for (bool trilinear : {false, true})
        for (bool perChannel : {false, true})
            for (bool specular : {false, true}) {
                std::vector<std::string> defines;
                if (trilinear) defines.push_back("EK_HARDWARE_TRILINEAR");
                if (perChannel) defines.push_back("EK_VIEW_PER_CHANNEL");
                if (specular) defines.push_back("EK_SPECULAR");
                list.push_back({"view.comp", defines});
            }
    // Light volumes: filtering.
    for (const char* file : {"light_sweep.comp", "light_march.comp"}) {
        list.push_back({file, none});
        list.push_back({file, {"EK_HARDWARE_TRILINEAR"}});
    }
    // The plane sweep's interleaved view: curved or straight rays, the curved with highlights
    // (always the window's exact filtering).
    list.push_back({"view_interleaved.comp", {"EK_FLUENCE_WINDOW"}});
    list.push_back({"view_interleaved.comp", {"EK_FLUENCE_WINDOW", "EK_INTERLEAVED_CURVED"}});
    list.push_back(
        {"view_interleaved.comp", {"EK_FLUENCE_WINDOW", "EK_INTERLEAVED_CURVED", "EK_SPECULAR"}});
    // The plane sweep: exact math.
    list.push_back({"plane_sweep.comp", none});
    list.push_back({"plane_sweep.comp", {"EK_EXACT_MATH"}});
    // Photons: exact math × the generating pass.
    for (bool exact : {false, true})
        for (bool generate : {false, true}) {
            std::vector<std::string> defines;
            if (exact) defines.push_back("EK_EXACT_MATH");
            if (generate) defines.push_back("EK_PHOTON_GENERATE");
            list.push_back({"photon_trace.comp", defines});
        }
    // The wavefront: exact math × the generating, tracing and scattering passes, and the prefix
    // sums.
    for (bool exact : {false, true})
        for (const char* pass : {"", "EK_WAVEFRONT_GENERATE", "EK_WAVEFRONT_SCATTER"}) {
            std::vector<std::string> defines;
            if (exact) defines.push_back("EK_EXACT_MATH");
            if (*pass) defines.push_back(pass);
            list.push_back({"wavefront_trace.comp", defines});
        }
    list.push_back({"wavefront_scan.comp", none});
    return list;
}

// Switches the shaders test that only C++ includers set (the shared headers' type-only parts, the
// CPU twin's empty-space steps, constant bricks, index volume, voxel size and blur weights) or
// that a shader defines itself.
const std::set<std::string> kNotVariants = {
    "EK_PHOTON_TYPES_ONLY", "EK_WAVEFRONT_TYPES_ONLY", "EK_PLANE_SWEEP_TYPES_ONLY",
    "EK_OCTREE_LEAF_RANGE", "EK_SKIP_EMPTY_SPACE",     "EK_CONSTANT_BRICKS",
    "EK_INDEX_VOLUME",      "EK_VOXEL_SIZE_MEMBER",    "EK_BLUR_WEIGHT_TABLE"};

// Runs a command, returning its exit status and its output (stdout and stderr).
int run(const std::string& command, std::string& output) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return -1;
    std::array<char, 4096> buffer{};
    while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
    return pclose(pipe);
}

std::string stageOf(const std::string& file) {
    return fs::path(file).extension().string().substr(1);  // comp, vert, frag
}

}  // namespace

TEST_CASE("every shader variant compiles under glslang, the Khronos reference compiler",
          "[gpu][glslang]") {
    std::string version;
    if (run("glslangValidator --version", version) != 0)
        FAIL("glslangValidator is missing: install glslang-tools (scripts/install-deps.sh)");

    const std::vector<Variant> list = variants();
    const fs::path dir = eikon::test::scratchDir("glslang");
    int index = 0;
    for (const Variant& v : list) {
        const eikon::ShaderSource source = eikon::expandShaderSource(v.file, v.defines);
        // glslang takes the stage from the extension.
        const fs::path file = dir / (std::to_string(index++) + "." + stageOf(v.file));
        std::ofstream(file) << source.text;
        std::string log;
        const int status = run("glslangValidator " + file.string(), log);
        std::string defines;
        for (const std::string& d : v.defines) defines += " " + d;
        INFO(v.file << " with {" << defines << " }:\n"
                    << eikon::rewriteShaderLog(log, source.files));
        CHECK(status == 0);
    }

    // Every shader file is in a variant (shaders/test/compile_error.comp fails on purpose).
    std::set<std::string> listed;
    for (const Variant& v : list) listed.insert(v.file);
    const fs::path root = eikon::shaderDirectory();
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".comp" && ext != ".vert" && ext != ".frag") continue;
        const std::string name = fs::relative(entry.path(), root).generic_string();
        if (name == "test/compile_error.comp" || name.rfind("test/sub/", 0) == 0) continue;
        INFO(name << " is in no variant: add it to variants()");
        CHECK(listed.count(name) == 1);
    }
    // Every switch the shaders test is set by some variant.
    std::set<std::string> set;
    for (const Variant& v : list) set.insert(v.defines.begin(), v.defines.end());
    const std::regex test(R"(#\s*if(n?def\s+|.*defined\s*\(\s*)(EK_[A-Z0-9_]+))");
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path());
        for (std::string line; std::getline(in, line);) {
            std::smatch m;
            if (!std::regex_search(line, m, test)) continue;
            const std::string name = m[2];
            if (kNotVariants.count(name)) continue;
            INFO(entry.path().filename().string()
                 << " tests " << name << ", which no variant sets");
            CHECK(set.count(name) == 1);
        }
    }
}
