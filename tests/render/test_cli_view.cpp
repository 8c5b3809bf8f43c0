// `eikon view`'s handle drag (apps/view_handles.h), run as a user would under a virtual X server:
// a scripted right drag of an ARAP handle moves the centre of its vertices in the deformed shape
// by exactly the drag on the image, in the camera plane, and prints the key that keeps the pose.
// A bad --drag fails before any window opens, in one line naming the handles there are.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "render/image.h"
#include "support/arap_ball_scene.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::arapBallScene;
using eikon::test::checkOneLineError;
using eikon::test::lines;
using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::sourcePath;
using eikon::test::writeFile;

namespace {

struct HandleReport {
    float x = NAN, y = NAN;              // where its marker is on the image
    float tx = NAN, ty = NAN, tz = NAN;  // the translation the printed key holds
};

// Reads "<prefix>handle ball/top at pixel (x, y); to keep this pose: {... "values": [[a, b, c]]}".
HandleReport findReport(const std::string& out, const std::string& prefix) {
    HandleReport r;
    for (const std::string& line : lines(out)) {
        if (line.rfind(prefix, 0) != 0) continue;
        const std::string pattern = prefix + "handle ball/top at pixel (%f, %f)";
        REQUIRE(std::sscanf(line.c_str(), pattern.c_str(), &r.x, &r.y) == 2);
        const size_t values = line.find("\"values\": [[");
        REQUIRE(values != std::string::npos);
        REQUIRE(std::sscanf(line.c_str() + values, "\"values\": [[%f, %f, %f]]", &r.tx, &r.ty,
                            &r.tz) == 3);
        CHECK(line.find("\"target\": \"/meshes/0/deformer/handles/1/translate\"") !=
              std::string::npos);
    }
    return r;
}

}  // namespace

TEST_CASE("eikon view drags an ARAP handle in the camera plane and prints the key to keep it",
          "[cli][view][arap]") {
#ifndef EIKON_XVFB_RUN
    WARN("xvfb-run was not found when this test was built: the viewer cannot run");
#else
    const std::string dir = scratchDir("cli_view_drag");
    const std::string scene = dir + "/ball.json";
    writeFile(scene, arapBallScene(48, 36));
    // The ball seen level from 3 units with a 40° field, 48x36 pixels. Frame 2 orbits 10° about the
    // vertical (as --exit-after does) and drags the top up 6 pixels.
    const RunResult r =
        runEikon("view " + quoted(scene) + " --exit-after 2 --drag ball/top:0,-6 --screenshot " +
                     quoted(dir + "/shot.png"),
                 dir, quoted(EIKON_XVFB_RUN) + " -a");
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(std::filesystem::exists(dir + "/shot.png"));
    const HandleReport before = findReport(r.out, "before the drag: ");
    const HandleReport after = findReport(r.out, "after the drag: ");
    // The centre of the top's vertices, in the shape the solver made, moved by the drag.
    constexpr float kPixels = 1e-2f;
    CHECK(after.x - before.x == Approx(0.0f).margin(kPixels));
    CHECK(after.y - before.y == Approx(-6.0f).margin(kPixels));
    // Seen level from 3 units (the orbit keeps the eye level and its distance), 6 of 48 pixels
    // across a 40° field is 3 · tan 20° · 6 / 24 straight up; the key holds that translation.
    const float up = 3.0f * std::tan(20.0f * 3.14159265f / 180.0f) * 6.0f / 24.0f;
    CHECK(before.ty == 0.0f);
    CHECK(after.tx == Approx(0.0f).margin(1e-3));
    CHECK(after.ty == Approx(up).margin(1e-3));
    CHECK(after.tz == Approx(0.0f).margin(1e-3));
    CHECK(r.out.find("frames rendered 2,") != std::string::npos);
#endif
}

TEST_CASE("a bad --drag fails before the window opens, naming the handles there are",
          "[cli][view][arap]") {
    const std::string dir = scratchDir("cli_view_bad_drag");
    const std::string scene = dir + "/ball.json";
    writeFile(scene, arapBallScene(48, 36));
    const RunResult unknown = runEikon("view " + quoted(scene) + " --drag ball/tip:0,5", dir);
    checkOneLineError(unknown, "--drag: ");
    CHECK(unknown.err.find("'ball/tip'") != std::string::npos);
    CHECK(unknown.err.find(scene) != std::string::npos);
    CHECK(unknown.err.find("ball/base, ball/top") != std::string::npos);
    const RunResult malformed = runEikon("view " + quoted(scene) + " --drag ball/top:5", dir);
    checkOneLineError(malformed, "--drag: ");
    CHECK(malformed.err.find("MESH/HANDLE:DX,DY") != std::string::npos);
}

// The three viewer scripts below tagged [release_only] run a photon scene 2-4 times each: 20-32 s
// apiece under the sanitizers (they passed there at f8c8f0b), where the panel's and the bad
// edits' cases keep the viewer's new code under ASan + UBSan within CI's time.
// The progressive viewer (apps/viewer.h): a change is rendered at 1/4 of the size and refined while
// nothing changes. The refined picture is the full-size render's, byte for byte (the window's
// pixels), and neither the smaller pictures nor the refinements trace the photons again.
TEST_CASE("eikon view refines a preview to the full-size picture and reuses the photons",
          "[cli][view][progressive][release_only]") {
#ifndef EIKON_XVFB_RUN
    WARN("xvfb-run was not found when this test was built: the viewer cannot run");
#else
    const std::string dir = scratchDir("cli_view_progressive");
    const std::string scene = sourcePath("data/scenes/glass_sphere_fog.json");
    const std::string common = "view " + quoted(scene) + " --size 64x48 --backend cpu";
    const RunResult progressive =
        runEikon(common + " --exit-after 2 --screenshot " + quoted(dir + "/progressive.png"), dir,
                 quoted(EIKON_XVFB_RUN) + " -a");
    INFO("stdout:\n" << progressive.out << "stderr:\n" << progressive.err);
    REQUIRE(progressive.exitCode == 0);
    // Two frames at 16x12, the second refined at 32x24 and 64x48: the first frame's preview
    // traces the photons lighter (half per side), the orbit traces nothing, and the first
    // refinement traces them as set (and one resample of each of the two fields, the glass and
    // the fog).
    CHECK(progressive.out.find("frames rendered 2, refinements 2, uploads 0, resamples 2, "
                               "gradients 1, octrees 1, photons runs 1, lighter previews 1") !=
          std::string::npos);
    CHECK(progressive.out.find("ms a frame at 1/4 size, ") != std::string::npos);
    const RunResult full = runEikon(
        common + " --exit-after 2 --preview-scale 1 --screenshot " + quoted(dir + "/full.png"), dir,
        quoted(EIKON_XVFB_RUN) + " -a");
    INFO("stdout:\n" << full.out << "stderr:\n" << full.err);
    REQUIRE(full.exitCode == 0);
    CHECK(full.out.find("frames rendered 2, refinements 0, uploads 0, resamples 2, gradients 1, "
                        "octrees 1, photons runs 1, lighter previews 0") != std::string::npos);
    CHECK(readFile(dir + "/progressive.png") == readFile(dir + "/full.png"));
    // Playing a live simulation: every frame is a change (the smoke moved), traced again, lighter,
    // at the preview size; the last frame, once the script stops playing, refines with one trace
    // as set.
    const RunResult playing =
        runEikon("view " + quoted(sourcePath("data/scenes/smoke_glass_mesh.json")) +
                     " --size 32x24 --backend cpu --play --exit-after 3",
                 dir, quoted(EIKON_XVFB_RUN) + " -a");
    INFO("stdout:\n" << playing.out << "stderr:\n" << playing.err);
    REQUIRE(playing.exitCode == 0);
    CHECK(playing.out.find("frames rendered 3, refinements 2, ") != std::string::npos);
    CHECK(playing.out.find("photons runs 1, lighter previews 3") != std::string::npos);
    CHECK(playing.out.find("octrees 3,") != std::string::npos);  // the smoke's κ moved
    // A preview scale that is not a power of two up to 16 is refused in one line.
    checkOneLineError(runEikon(common + " --preview-scale 3", dir), "view: --preview-scale: ");
#endif
}

// Edits (apps/view_edits.h, the relighting panel's path, scripted by --edit): after the first
// frame a light's intensity reruns the photons alone, a glass's n the ∇n volume, the octree and
// the photons; the JSON Patch printed keeps the edit: the scene patched so renders the edited
// picture byte for byte.
TEST_CASE("eikon view --edit reruns only the stages it touches, and its JSON Patch keeps it",
          "[cli][view][edit][release_only]") {
#ifndef EIKON_XVFB_RUN
    WARN("xvfb-run was not found when this test was built: the viewer cannot run");
#else
    const std::string dir = scratchDir("cli_view_edit");
    const std::string scene = sourcePath("data/scenes/glass_sphere_fog.json");
    const std::string xvfb = quoted(EIKON_XVFB_RUN) + " -a";
    const std::string common = " --size 64x48 --backend cpu --exit-after 2 --screenshot ";
    const RunResult light =
        runEikon("view " + quoted(scene) + common + quoted(dir + "/edited.png") +
                     " --edit /lights/0/intensity=45",
                 dir, xvfb);
    INFO("stdout:\n" << light.out << "stderr:\n" << light.err);
    REQUIRE(light.exitCode == 0);
    CHECK(light.out.find("patch the scene with [{\"op\": \"add\", \"path\": "
                         "\"/lights/0/intensity\", \"value\": 45}]") != std::string::npos);
    // Each frame's preview traces lighter; the refinement of the edited frame traces as set.
    CHECK(light.out.find("gradients 1, octrees 1, photons runs 1, lighter previews 2") !=
          std::string::npos);
    // Previews traced as set: twice the full trace, and the same refined picture.
    const RunResult asSet =
        runEikon("view " + quoted(scene) + common + quoted(dir + "/as_set.png") +
                     " --edit /lights/0/intensity=45 --preview-light full",
                 dir, xvfb);
    INFO("stdout:\n" << asSet.out << "stderr:\n" << asSet.err);
    REQUIRE(asSet.exitCode == 0);
    CHECK(asSet.out.find("photons runs 2, lighter previews 0") != std::string::npos);
    CHECK(readFile(dir + "/as_set.png") == readFile(dir + "/edited.png"));

    const RunResult index = runEikon("view " + quoted(scene) + common + quoted(dir + "/index.png") +
                                         " --edit /materials/1/ior=1.7 --edit /materials/1/ior=1.6",
                                     dir, xvfb);
    INFO("stdout:\n" << index.out << "stderr:\n" << index.err);
    REQUIRE(index.exitCode == 0);
    // The later edit of one pointer replaces the earlier.
    CHECK(index.out.find("[{\"op\": \"add\", \"path\": \"/materials/1/ior\", \"value\": 1.6}]") !=
          std::string::npos);
    CHECK(index.out.find("gradients 2, octrees 2, photons runs 1, lighter previews 2") !=
          std::string::npos);

    // The method: the picture after the edit is the plane sweep's.
    const RunResult method =
        runEikon("view " + quoted(scene) + common + quoted(dir + "/method.png") +
                     " --edit /render/light_transport/method=plane_sweep",
                 dir, xvfb);
    INFO("stdout:\n" << method.out << "stderr:\n" << method.err);
    REQUIRE(method.exitCode == 0);
    CHECK(method.out.find("[{\"op\": \"add\", \"path\": \"/render/light_transport/method\", "
                          "\"value\": \"plane_sweep\"}]") != std::string::npos);
    CHECK(method.out.find("plane_sweep runs 1") != std::string::npos);

    // The method's settings: fewer photons, traced again; the patch adds the whole section.
    const RunResult settings =
        runEikon("view " + quoted(scene) + common + quoted(dir + "/settings.png") + " --edit " +
                     quoted("/render/light_transport={\"photons\": {\"per_side\": 64}}"),
                 dir, xvfb);
    INFO("stdout:\n" << settings.out << "stderr:\n" << settings.err);
    REQUIRE(settings.exitCode == 0);
    CHECK(settings.out.find("[{\"op\": \"add\", \"path\": \"/render/light_transport\", "
                            "\"value\": {\"photons\":{\"per_side\":64}}}]") != std::string::npos);
    CHECK(settings.out.find("photons runs 1, lighter previews 2") != std::string::npos);

    // The patch applied by hand: the file says 45 where it said 30.
    std::string text = readFile(scene);
    const std::string from = "\"intensity\": 30,";
    REQUIRE(text.find(from) != std::string::npos);
    text.replace(text.find(from), from.size(), "\"intensity\": 45,");
    writeFile(dir + "/patched.json", text);
    const RunResult patched = runEikon(
        "view " + quoted(dir + "/patched.json") + common + quoted(dir + "/patched.png"), dir, xvfb);
    REQUIRE(patched.exitCode == 0);
    CHECK(readFile(dir + "/patched.png") == readFile(dir + "/edited.png"));
    CHECK(readFile(dir + "/patched.png") != readFile(dir + "/index.png"));
#endif
}

// A material's colour map (the panel's "particle colour" list, --edit with a map's name): the
// edited picture is the scene's with that particle colour, byte for byte, and the JSON Patch
// printed says so; "none" takes a colour away, and removes it from the file where it was. A
// colour, like the phase function's g, reruns the view alone.
TEST_CASE("eikon view --edit picks a material's colour map, and its JSON Patch keeps it",
          "[cli][view][edit][release_only]") {
#ifndef EIKON_XVFB_RUN
    WARN("xvfb-run was not found when this test was built: the viewer cannot run");
#else
    const std::string dir = scratchDir("cli_view_color_map");
    const std::string scene = sourcePath("data/scenes/glass_sphere_fog.json");
    const std::string xvfb = quoted(EIKON_XVFB_RUN) + " -a";
    const std::string common = " --size 64x48 --backend cpu --exit-after 2 --screenshot ";
    const RunResult edited =
        runEikon("view " + quoted(scene) + common + quoted(dir + "/edited.png") +
                     " --edit /materials/0/particle_color=viridis"
                     " --edit /materials/0/particle_color=magma",
                 dir, xvfb);
    INFO("stdout:\n" << edited.out << "stderr:\n" << edited.err);
    REQUIRE(edited.exitCode == 0);
    // The later edit of one material replaces the earlier; the range is the default's.
    CHECK(edited.out.find("patch the scene with [{\"op\": \"add\", \"path\": "
                          "\"/materials/0/particle_color\", \"value\": {\"map\": \"magma\", "
                          "\"range\": [0, 1]}}]") != std::string::npos);
    // A colour reruns only the view: the octree and the photons are the first frame's (whose
    // preview traced lighter once).
    CHECK(edited.out.find("gradients 1, octrees 1, photons runs 1, lighter previews 1") !=
          std::string::npos);
    // So does the phase function's g, which only the view applies.
    const RunResult phase = runEikon("view " + quoted(scene) + common + quoted(dir + "/phase.png") +
                                         " --edit /materials/0/g=0.5",
                                     dir, xvfb);
    INFO("stdout:\n" << phase.out << "stderr:\n" << phase.err);
    REQUIRE(phase.exitCode == 0);
    CHECK(phase.out.find("gradients 1, octrees 1, photons runs 1, lighter previews 1") !=
          std::string::npos);
    const RunResult plain =
        runEikon("view " + quoted(scene) + common + quoted(dir + "/plain.png"), dir, xvfb);
    REQUIRE(plain.exitCode == 0);
    CHECK(readFile(dir + "/plain.png") != readFile(dir + "/edited.png"));

    // The patch applied by hand: the fog tinted by magma in the file.
    std::string text = readFile(scene);
    const std::string from = "\"g\": 0.3 }";
    REQUIRE(text.find(from) != std::string::npos);
    text.replace(text.find(from), from.size(), "\"g\": 0.3, \"particle_color\": \"magma\" }");
    writeFile(dir + "/patched.json", text);
    const RunResult patched = runEikon(
        "view " + quoted(dir + "/patched.json") + common + quoted(dir + "/patched.png"), dir, xvfb);
    INFO("stdout:\n" << patched.out << "stderr:\n" << patched.err);
    REQUIRE(patched.exitCode == 0);
    CHECK(readFile(dir + "/patched.png") == readFile(dir + "/edited.png"));

    // "none" on the patched file: the plain picture, and the patch removes the colour.
    const RunResult none =
        runEikon("view " + quoted(dir + "/patched.json") + common + quoted(dir + "/none.png") +
                     " --edit /materials/0/particle_color=none",
                 dir, xvfb);
    REQUIRE(none.exitCode == 0);
    CHECK(none.out.find("[{\"op\": \"remove\", \"path\": \"/materials/0/particle_color\"}]") !=
          std::string::npos);
    CHECK(readFile(dir + "/none.png") == readFile(dir + "/plain.png"));
#endif
}

TEST_CASE("a bad --edit fails before the window opens, in one line", "[cli][view][edit]") {
    const std::string dir = scratchDir("cli_view_bad_edit");
    const std::string scene = quoted(sourcePath("data/scenes/glass_sphere_fog.json"));
    const struct {
        const char* edit;
        const char* says;
    } cases[] = {
        {"/lights/0/intensity", "is not POINTER=VALUE"},
        {"/lights/3/intensity=2", "no lights 3 (the scene has 1)"},
        {"/camera/position=0,0,5", "the viewer edits lights, materials and clip planes"},
        {"/lights/0/color=1,1", "takes 3 numbers, not 2"},
        {"/lights/0/intensity=nan", "not finite numbers"},
        {"/lights/0/intensity=2x", "not finite numbers"},
        {"/render/light_transport/method=rays",
         "no light-transport method 'rays' (there are auto, "},
        {"/materials/0/particle_color=teal", "no colour map 'teal' (there are none, viridis"},
        {"/materials/5/particle_color=magma", "no materials 5"},
        {"/materials/x/particle_color=magma", "'x' is not a material's index"},
    };
    for (const auto& c : cases) {
        const RunResult r = runEikon("view " + scene + " --edit " + quoted(c.edit), dir);
        INFO(c.edit);
        checkOneLineError(r, "--edit: ");
        CHECK(r.err.find(c.says) != std::string::npos);
    }
}

// The relighting panel (apps/view_panel.h) is drawn over the picture's top left corner and
// nowhere else: the window with the panel and the picture alone differ there, and are the same
// bytes beyond the panel's width. --screenshot keeps the picture alone.
TEST_CASE("eikon view draws its panel over the picture's corner and leaves the rest",
          "[cli][view][panel]") {
#ifndef EIKON_XVFB_RUN
    WARN("xvfb-run was not found when this test was built: the viewer cannot run");
#else
    const std::string dir = scratchDir("cli_view_panel");
    const RunResult r = runEikon("view " + quoted(sourcePath("data/scenes/fog_sphere_spot.json")) +
                                     " --size 640x480 --backend cpu --exit-after 1 --screenshot " +
                                     quoted(dir + "/picture.png") + " --panel-screenshot " +
                                     quoted(dir + "/panel.png"),
                                 dir, quoted(EIKON_XVFB_RUN) + " -a");
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    const eikon::Image picture = eikon::readPng(dir + "/picture.png");
    const eikon::Image panel = eikon::readPng(dir + "/panel.png");
    REQUIRE(picture.width == 640);
    REQUIRE(panel.width == 640);
    int changedInCorner = 0, changedBeyond = 0;
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 640; ++x) {
            const bool differs = picture.at(x, y) != panel.at(x, y);
            if (x < 300 && y < 100) changedInCorner += differs;
            if (x >= 400) changedBeyond += differs;
        }
    CHECK(changedInCorner > 300 * 100 / 2);  // the panel's title, figures and buttons
    CHECK(changedBeyond == 0);
#endif
}

namespace {

// Reads "<prefix>light 0 at pixel (x, y); ..." from the viewer's output.
glm::vec2 lightPixel(const std::string& out, const std::string& prefix) {
    glm::vec2 at(NAN);
    for (const std::string& line : lines(out))
        if (line.rfind(prefix, 0) == 0)
            REQUIRE(std::sscanf(line.c_str() + prefix.size(), "light 0 at pixel (%f, %f)", &at.x,
                                &at.y) == 2);
    return at;
}

}  // namespace

// A light's gizmo (apps/light_gizmos.h), dragged as a right drag would: a spot light's square
// follows the drag exactly (its position moves in the camera plane), a directional light's too
// while the cursor stays over its sphere (its direction turns); the drag is an edit that reruns
// the light's transport, and the patch printed keeps it.
TEST_CASE("eikon view drags a light's gizmo, and prints the patch that keeps the light there",
          "[cli][view][light][release_only]") {
#ifndef EIKON_XVFB_RUN
    WARN("xvfb-run was not found when this test was built: the viewer cannot run");
#else
    const std::string dir = scratchDir("cli_view_light_drag");
    const std::string xvfb = quoted(EIKON_XVFB_RUN) + " -a";
    const RunResult spot =
        runEikon("view " + quoted(sourcePath("data/scenes/glass_sphere_fog.json")) +
                     " --size 64x48 --backend cpu --exit-after 2 --drag lights/0:0,-6",
                 dir, xvfb);
    INFO("stdout:\n" << spot.out << "stderr:\n" << spot.err);
    REQUIRE(spot.exitCode == 0);
    const glm::vec2 moved =
        lightPixel(spot.out, "after the drag: ") - lightPixel(spot.out, "before the drag: ");
    CHECK(moved.x == Approx(0.0f).margin(1e-2));
    CHECK(moved.y == Approx(-6.0f).margin(1e-2));
    CHECK(spot.out.find("[{\"op\": \"add\", \"path\": \"/lights/0/position\", \"value\": [") !=
          std::string::npos);
    CHECK(spot.out.find("photons runs 1, lighter previews 2") != std::string::npos);

    const RunResult sun = runEikon("view " + quoted(sourcePath("data/scenes/water_pool.json")) +
                                       " --size 64x48 --backend cpu --exit-after 2 --drag "
                                       "lights/0:1,2",
                                   dir, xvfb);
    INFO("stdout:\n" << sun.out << "stderr:\n" << sun.err);
    REQUIRE(sun.exitCode == 0);
    const glm::vec2 turned =
        lightPixel(sun.out, "after the drag: ") - lightPixel(sun.out, "before the drag: ");
    CHECK(turned.x == Approx(1.0f).margin(1e-2));
    CHECK(turned.y == Approx(2.0f).margin(1e-2));
    const size_t at = sun.out.find("\"path\": \"/lights/0/direction\", \"value\": [");
    REQUIRE(at != std::string::npos);
    glm::vec3 d(NAN);
    REQUIRE(std::sscanf(sun.out.c_str() + sun.out.find('[', at + 20), "[%f, %f, %f]", &d.x, &d.y,
                        &d.z) == 3);
    CHECK(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) == Approx(1.0f).margin(1e-6));

    const RunResult none = runEikon(
        "view " + quoted(sourcePath("data/scenes/glass_sphere_fog.json")) + " --drag lights/1:0,1",
        dir);
    checkOneLineError(none, "--drag: ");
    CHECK(none.err.find("no light 'lights/1' (the scene has 1 light") != std::string::npos);
#endif
}

// A frame budget (--frame-budget, render/preview_budget.h): after each change the next one is
// rendered at the finest size whose predicted time fits. The outcomes that do not depend on the
// machine's speed: a budget no frame can miss makes every change after the second full size (no
// refinement left to do), one no frame can meet makes it 1/16 (four refinements to full size).
TEST_CASE("eikon view's frame budget picks the preview's size from the frame times",
          "[cli][view][progressive]") {
#ifndef EIKON_XVFB_RUN
    WARN("xvfb-run was not found when this test was built: the viewer cannot run");
#else
    const std::string dir = scratchDir("cli_view_budget");
    const std::string common = "view " + quoted(sourcePath("data/scenes/homogeneous_cube.json")) +
                               " --size 32x32 --backend cpu --exit-after 3";
    const RunResult generous =
        runEikon(common + " --frame-budget 1000000", dir, quoted(EIKON_XVFB_RUN) + " -a");
    INFO("stdout:\n" << generous.out << "stderr:\n" << generous.err);
    REQUIRE(generous.exitCode == 0);
    // The first frame (loading) does not guide; the second, at 1/4, says full size fits.
    CHECK(generous.out.find("frames rendered 3, refinements 0, ") != std::string::npos);
    CHECK(generous.out.find(" a frame at 1/1 to 1/4 size, ") != std::string::npos);
    const RunResult tight =
        runEikon(common + " --frame-budget 0.000001", dir, quoted(EIKON_XVFB_RUN) + " -a");
    INFO("stdout:\n" << tight.out << "stderr:\n" << tight.err);
    REQUIRE(tight.exitCode == 0);
    CHECK(tight.out.find("frames rendered 3, refinements 4, ") != std::string::npos);
    CHECK(tight.out.find(" a frame at 1/4 to 1/16 size, ") != std::string::npos);
    // Without a budget a scripted run keeps --preview-scale: two refinements from 1/4.
    const RunResult fixed = runEikon(common, dir, quoted(EIKON_XVFB_RUN) + " -a");
    INFO("stdout:\n" << fixed.out << "stderr:\n" << fixed.err);
    REQUIRE(fixed.exitCode == 0);
    CHECK(fixed.out.find("frames rendered 3, refinements 2, ") != std::string::npos);
    checkOneLineError(runEikon(common + " --frame-budget -5", dir), "view: --frame-budget: ");
#endif
}
