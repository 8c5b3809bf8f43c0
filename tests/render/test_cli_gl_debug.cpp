// The whole GPU pipeline under OpenGL debug output (`eikon render --gl-debug`, GL_KHR_debug): the
// driver reports no error, no undefined behaviour and no warning on any stage, for scenes that
// together run every GPU pass — ∇n and the octree, photons with their rounds and resolve, light
// volumes (swept and marched), receivers, mesh voxelization and blur, a VDB smoke, the view pass
// with Fresnel, and dispersion's per-channel dispatches.
#include <catch2/catch.hpp>

#include <string>

#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::quoted;
using eikon::test::runEikon;

TEST_CASE("the GPU pipeline runs with no OpenGL error or warning under --gl-debug",
          "[cli][gl][debug]") {
    const std::string dir = eikon::test::scratchDir("cli_gl_debug");
    for (const char* scene : {"glass_sphere_fog", "fog_sphere_spot", "glass_mesh_floor",
                              "houdini_smoke", "crystal_dispersion", "light_circling_glass"}) {
        const std::string path = eikon::test::sourcePath("data/scenes/") + scene + ".json";
        const eikon::test::RunResult r =
            runEikon("render " + quoted(path) + " --backend gpu --gl-debug --size 32x24 -o " +
                         quoted(dir + "/") + " --frames 0",
                     dir);
        INFO(scene << ":\n" << r.err);
        CHECK(r.exitCode == 0);
        // The debug output was on (the backend line on stdout says so), and said nothing.
        CHECK(r.out.find("OpenGL debug output on") != std::string::npos);
        CHECK(r.err.find("OpenGL debug (") == std::string::npos);
    }
}
