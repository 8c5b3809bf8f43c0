// The strict scene parser: the shipped scenes and the documented example parse, defaults apply,
// and every class of mistake gives an error with the JSON pointer and the expected form.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/scene.h"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

// Smallest valid scene body; tests append the keys they exercise.
const std::string kMinimalBody = R"("sources": [{"type": "sphere"}], "materials": [{"name": "m"}])";

std::string sceneWith(const std::string& extraKeys) {
    return "{" + kMinimalBody + (extraKeys.empty() ? "" : ", " + extraKeys) + "}";
}

struct Failure {
    std::string where;
    std::string reason;
    std::string message;
};

// Parses `text` as smoke.json and returns the error it must raise.
Failure failureOf(const std::string& text) {
    try {
        eikon::parseScene(text, "smoke.json");
    } catch (const eikon::Error& e) {
        return {e.where(), e.reason(), e.what()};
    }
    FAIL("expected an eikon::Error for: " << text);
    return {};
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The first ```json block after the "## Complete example" heading of the format's documentation.
std::string documentedExample() {
    const std::string doc = readFile(fs::path(EIKON_SOURCE_DIR) / "docs" / "scene-format.md");
    const std::size_t section = doc.find("## Complete example");
    REQUIRE(section != std::string::npos);
    const std::string fence = "```json\n";
    const std::size_t begin = doc.find(fence, section);
    REQUIRE(begin != std::string::npos);
    const std::size_t end = doc.find("```", begin + fence.size());
    REQUIRE(end != std::string::npos);
    return doc.substr(begin + fence.size(), end - begin - fence.size());
}

}  // namespace

TEST_CASE("every scene in data/scenes parses", "[scene]") {
    const fs::path folder = fs::path(EIKON_SOURCE_DIR) / "data" / "scenes";
    int parsed = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        INFO(entry.path().string());
        eikon::Scene scene;
        REQUIRE_NOTHROW(scene = eikon::loadScene(entry.path().string()));
        CHECK(scene.path == entry.path().string());
        CHECK((!scene.sources.empty() || !scene.meshes.empty()));  // something to render
        CHECK_FALSE(scene.materials.empty());
        // VDB paths are resolved against the scene's folder, so they name real files; a scene
        // with a simulation renders the cache `eikon simulate` writes, which is not shipped.
        for (const eikon::SourceSpec& source : scene.sources) {
            const bool simulated =
                !scene.simulations.empty() &&
                fs::path(source.file).parent_path() == scene.simulations.at(0).cacheDirectory;
            if (!simulated && (source.type == eikon::SourceType::Vdb ||
                               source.type == eikon::SourceType::VdbSequence)) {
                CHECK(fs::exists(source.file));
            }
        }
        ++parsed;
    }
    CHECK(parsed >= 3);
}

TEST_CASE("the shipped scenes hold what they say", "[scene]") {
    const fs::path folder = fs::path(EIKON_SOURCE_DIR) / "data" / "scenes";

    SECTION("homogeneous cube") {
        const eikon::Scene scene = eikon::loadScene((folder / "homogeneous_cube.json").string());
        REQUIRE(scene.sources.size() == 1);
        CHECK(scene.sources[0].type == eikon::SourceType::Box);
        CHECK(scene.sources[0].boxMin == glm::vec3(-1.0f));
        CHECK(scene.sources[0].boxMax == glm::vec3(1.0f));
        CHECK(scene.materials[0].name == "absorber");
        CHECK(scene.materials[0].absorption == glm::vec3(0.5f));
        CHECK(scene.materials[0].scattering == glm::vec3(0.0f));
        CHECK(scene.lights.empty());
        CHECK_FALSE(scene.camera.automatic);
        CHECK(scene.camera.position == glm::vec3(0.0f, 0.0f, 6.0f));
        CHECK(scene.environment.color == glm::vec3(1.0f));
        CHECK(scene.render.width == 160);
        CHECK(scene.render.height == 120);
        CHECK(scene.output.png);
        CHECK(scene.output.exr);
    }
    SECTION("houdini smoke: the light travels away from vdb_render's -light 1,1,0.5") {
        const eikon::Scene scene = eikon::loadScene((folder / "houdini_smoke.json").string());
        REQUIRE(scene.lights.size() == 1);
        const glm::vec3 d = scene.lights[0].direction;
        CHECK(d.x == Approx(-2.0 / 3.0).margin(1e-6));
        CHECK(d.y == Approx(-2.0 / 3.0).margin(1e-6));
        CHECK(d.z == Approx(-1.0 / 3.0).margin(1e-6));
        CHECK(scene.volume.autoBounds);
        CHECK(scene.volume.autoResolution);
        CHECK(scene.materials[0].scattering.x == Approx(0.3 / 0.476).epsilon(1e-5));
        CHECK(scene.materials[0].absorption.x == Approx(0.05 / 0.476).epsilon(1e-5));
        CHECK(scene.sources[0].jsonPath == "/sources/0");
    }
    SECTION("blender smoke sequence") {
        const eikon::Scene scene =
            eikon::loadScene((folder / "blender_smoke_sequence.json").string());
        CHECK(scene.sources[0].type == eikon::SourceType::VdbSequence);
        REQUIRE(scene.lights.size() == 1);
        CHECK(scene.lights[0].type == eikon::LightType::Spot);
        CHECK(glm::length(scene.lights[0].direction) == Approx(1.0f));
        CHECK(scene.time.frameStart == 1);
        CHECK(scene.time.frameEnd == 10);
    }
    SECTION("glass sphere over a floor: the floor is a receiver plane below the sphere") {
        const eikon::Scene scene = eikon::loadScene((folder / "glass_sphere_floor.json").string());
        REQUIRE(scene.receivers.size() == 1);
        CHECK(scene.receivers[0].axis == 1);
        CHECK(scene.receivers[0].facing == 1);
        CHECK(scene.receivers[0].method == eikon::ReceiverMethod::Plane);
        REQUIRE(scene.sources.size() == 2);
        CHECK(scene.receivers[0].position < scene.sources[1].center.y - scene.sources[1].radius);
    }
    SECTION("smoke around a glass mesh: the rendered glass is the obstacle, the source moves") {
        const eikon::Scene scene = eikon::loadScene((folder / "smoke_glass_mesh.json").string());
        REQUIRE(scene.simulations.size() == 1);
        REQUIRE(scene.sources.size() == 1);
        CHECK(scene.sources[0].type == eikon::SourceType::Simulation);  // stepped live
        REQUIRE(scene.simulations.at(0).obstacles.size() == 1);
        CHECK(scene.simulations.at(0).obstacles[0].kind == eikon::SimShapeSpec::Kind::Mesh);
        CHECK(scene.meshes[std::size_t(scene.simulations.at(0).obstacles[0].mesh)].name == "glass");
        REQUIRE(scene.animation.size() == 1);
        CHECK(scene.animation[0].target == "/simulation/sources/0/center");
        // The source's path stays below the glass (centre y 0.75, radius 0.25).
        for (std::size_t v = 1; v < scene.animation[0].values.size(); v += 3)
            CHECK(scene.animation[0].values[v] + scene.simulations.at(0).sources[0].shape.radius <
                  0.5f);
    }
}

TEST_CASE("a simulation source needs the scene's simulation", "[scene]") {
    const std::string materials =
        R"("materials": [{"name": "smoke", "field": "density", "scattering": [1, 1, 1]},
        {"name": "air", "field": "temperature", "gladstone_dale": 0.01}])";
    CHECK_THROWS_WITH(
        eikon::parseScene(R"({"sources": [{"type": "simulation"}], )" + materials + "}", "s.json"),
        Catch::Contains("s.json:/sources/0/type") && Catch::Contains("no \"simulation\" section"));
    const eikon::Scene scene = eikon::parseScene(
        R"({"sources": [{"type": "simulation"}], )" + materials +
            R"(, "simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": 8}})",
        "s.json");
    CHECK(scene.sources[0].type == eikon::SourceType::Simulation);
    CHECK_THROWS_WITH(
        eikon::parseScene(
            R"({"sources": [{"type": "simulation", "file": "a.vdb"}], )" + materials +
                R"(, "simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": 8}})",
            "s.json"),
        Catch::Contains("s.json:/sources/0/file") && Catch::Contains("unknown key"));
}

TEST_CASE("render.integrator names the view rays' integrator, others are errors", "[scene]") {
    const std::string head =
        R"({"sources": [{"type": "sphere", "field": "n"}], "materials": [{"name": "glass", )"
        R"("field": "n", "ior": 1.5}], "render": {"integrator": )";
    for (const std::string& name : eikon::rayIntegratorNames()) {
        const eikon::Scene scene = eikon::parseScene(head + "\"" + name + "\"}}", "s.json");
        CHECK(eikon::rayIntegratorName(scene.render.integrator) == name);
    }
    CHECK_THROWS_WITH(
        eikon::parseScene(head + "\"rk5\"}}", "s.json"),
        Catch::Contains("s.json:/render/integrator") && Catch::Contains("did you mean \"rk4\""));
}

TEST_CASE("the example in docs/scene-format.md parses", "[scene]") {
    const std::string docPath = std::string(EIKON_SOURCE_DIR) + "/docs/scene-format.md";
    eikon::Scene scene;
    REQUIRE_NOTHROW(scene = eikon::parseScene(documentedExample(), docPath));
    CHECK(scene.sources.size() == 3);
    CHECK(scene.materials.size() == 3);
    CHECK(scene.lights.size() == 3);
    CHECK_FALSE(scene.volume.autoBounds);
    CHECK(scene.volume.resolution == glm::ivec3(128));
    CHECK(scene.time.frameEnd == 48);
    // Relative paths resolve against the folder of the file named for messages.
    CHECK(scene.sources[0].file ==
          (fs::path(EIKON_SOURCE_DIR) / "docs" / "caches" / "plume_####.vdb")
              .lexically_normal()
              .string());
    CHECK(scene.sources[0].aliases.at("density") == std::vector<std::string>{"soot_fine"});
}

TEST_CASE("a minimal scene gets the documented defaults", "[scene]") {
    const eikon::Scene scene = eikon::parseScene(sceneWith(""), "minimal.json");
    const eikon::Scene model;

    CHECK(scene.volume.autoBounds);
    CHECK(scene.volume.autoResolution);
    CHECK(scene.volume.maxResolution == 256);

    REQUIRE(scene.sources.size() == 1);
    const eikon::SourceSpec& sphere = scene.sources[0];
    CHECK(sphere.type == eikon::SourceType::Sphere);
    CHECK(sphere.field == "density");
    CHECK(sphere.center == glm::vec3(0.0f));
    CHECK(sphere.radius == 1.0f);
    CHECK(sphere.value == 1.0f);
    CHECK(sphere.falloff == 0.0f);
    CHECK(sphere.voxelSize == 0.05f);

    REQUIRE(scene.materials.size() == 1);
    const eikon::MaterialSpec& material = scene.materials[0];
    CHECK(material.name == "m");
    CHECK(material.field == "density");
    CHECK(material.absorption == glm::vec3(0.0f));
    CHECK(material.scattering == glm::vec3(0.0f));
    CHECK(material.g == 0.0f);
    CHECK(material.emission == glm::vec3(0.0f));
    CHECK(material.ior == 1.0f);

    CHECK(scene.lights.empty());
    CHECK(scene.camera.automatic);
    CHECK(scene.environment.color == glm::vec3(0.0f));
    CHECK(scene.render.width == 640);
    CHECK(scene.render.height == 480);
    CHECK(scene.render.stepVoxels == 1.0f);
    CHECK(scene.render.integrator == eikon::RayIntegrator::Verlet);
    CHECK(scene.render.lightTransport == "{}");
    CHECK(scene.render.minTransmittance == model.render.minTransmittance);
    CHECK(scene.render.exposure == 0.0f);
    CHECK(scene.render.seed == 0u);
    CHECK(scene.output.directory == "out");
    CHECK(scene.output.name == "frame");
    CHECK(scene.output.png);
    CHECK_FALSE(scene.output.exr);
    CHECK(scene.time.fps == 24.0);
    CHECK(scene.time.frameStart == 0);
    CHECK(scene.time.frameEnd == 0);
}

TEST_CASE("defaults inside sections that are present", "[scene]") {
    SECTION("a light gets colour, intensity and cone defaults; its direction is normalised") {
        const eikon::Scene scene = eikon::parseScene(
            sceneWith(
                R"("lights": [{"type": "spot", "position": [0, 4, 0], "direction": [0, -2, 0]}])"),
            "s.json");
        const eikon::LightSpec& spot = scene.lights.at(0);
        CHECK(spot.color == glm::vec3(1.0f));
        CHECK(spot.intensity == 1.0f);
        CHECK(spot.coneAngleDeg == 30.0f);
        CHECK(spot.coneSoftnessDeg == 5.0f);
        CHECK(spot.direction == glm::vec3(0.0f, -1.0f, 0.0f));
    }
    SECTION("a directional light's disc: 0 unless given, its angle as given") {
        const eikon::Scene scene = eikon::parseScene(
            sceneWith(R"("lights": [{"type": "directional", "direction": [0, -1, 0]},
                                    {"type": "directional", "direction": [0, -1, 0],
                                     "angular_diameter_deg": 0.53}])"),
            "s.json");
        CHECK(scene.lights.at(0).angularDiameterDeg == 0.0f);
        CHECK(scene.lights.at(1).angularDiameterDeg == 0.53f);
    }
    SECTION("a narrow cone shrinks the default softness to fit") {
        const eikon::Scene scene =
            eikon::parseScene(sceneWith(R"("lights": [{"type": "spot", "position": [0, 4, 0],
                                     "direction": [0, -1, 0], "cone_angle_deg": 2}])"),
                              "s.json");
        CHECK(scene.lights.at(0).coneSoftnessDeg == 2.0f);
    }
    SECTION("a camera object gets the remaining defaults and is not automatic") {
        const eikon::Scene scene =
            eikon::parseScene(sceneWith(R"("camera": {"position": [1, 2, 3]})"), "s.json");
        CHECK_FALSE(scene.camera.automatic);
        CHECK(scene.camera.lookAt == glm::vec3(0.0f));
        CHECK(scene.camera.up == glm::vec3(0.0f, 1.0f, 0.0f));
        CHECK(scene.camera.horizontalFovDeg == 45.0f);
    }
    SECTION("frame_end defaults to frame_start") {
        const eikon::Scene scene =
            eikon::parseScene(sceneWith(R"("time": {"frame_start": 12})"), "s.json");
        CHECK(scene.time.frameEnd == 12);
    }
    SECTION("one integer resolution means a cube; integral floats are integers") {
        const eikon::Scene scene =
            eikon::parseScene(sceneWith(R"("volume": {"resolution": 32.0})"), "s.json");
        CHECK_FALSE(scene.volume.autoResolution);
        CHECK(scene.volume.resolution == glm::ivec3(32));
    }
    SECTION("the full uint32 range of seeds") {
        const eikon::Scene scene =
            eikon::parseScene(sceneWith(R"("render": {"seed": 4294967295})"), "s.json");
        CHECK(scene.render.seed == 4294967295u);
    }
}

TEST_CASE("unknown keys are errors with a did-you-mean hint", "[scene]") {
    SECTION("misspelt light key") {
        const Failure f = failureOf(
            sceneWith(R"("lights": [{"type": "point", "position": [0, 1, 0], "intesity": 2}])"));
        CHECK(f.where == "smoke.json:/lights/0/intesity");
        CHECK_THAT(f.reason, Contains("unknown key 'intesity'"));
        CHECK_THAT(f.reason, Contains("did you mean 'intensity'?"));
        CHECK_THAT(f.reason, Contains("expected one of: type, position, color, intensity"));
    }
    SECTION("misspelt nested key") {
        const Failure f =
            failureOf(sceneWith(R"("volume": {"bounds": {"min": [0, 0, 0], "maks": [1, 1, 1]}})"));
        // "max" is required, so its absence is what is reported, pointing at the likely typo.
        CHECK(f.where == "smoke.json:/volume/bounds/max");
        CHECK_THAT(f.reason, Contains("missing required key 'max'"));
        CHECK_THAT(f.reason, Contains("'maks'"));
    }
    SECTION("misspelt key inside a section with everything else valid") {
        const Failure f = failureOf(sceneWith(R"("render": {"widht": 320})"));
        CHECK(f.where == "smoke.json:/render/widht");
        CHECK_THAT(f.reason, Contains("did you mean 'width'?"));
    }
    SECTION("camelCase spelling of a snake_case key") {
        const Failure f = failureOf(sceneWith(R"("camera": {"lookAt": [0, 0, 1]})"));
        CHECK(f.where == "smoke.json:/camera/lookAt");
        CHECK_THAT(f.reason, Contains("did you mean 'look_at'?"));
    }
    SECTION("unknown top-level key") {
        const Failure f = failureOf(sceneWith(R"("lihgts": [])"));
        CHECK(f.where == "smoke.json:/lihgts");
        CHECK_THAT(f.reason, Contains("did you mean 'lights'?"));
    }
    SECTION("a key of another source type") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "vdb", "file": "a.vdb", "radius": 2}], "materials": [{"name": "m"}]})");
        CHECK(f.where == "smoke.json:/sources/0/radius");
        CHECK_THAT(f.reason, Contains("unknown key 'radius' for a vdb source"));
        CHECK_THAT(f.reason, Contains("expected one of: type, file, aliases"));
    }
    SECTION("an alias for a field that is not canonical") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "vdb", "file": "a.vdb", "aliases": {"densty": ["soot"]}}],
                "materials": [{"name": "m"}]})");
        CHECK(f.where == "smoke.json:/sources/0/aliases/densty");
        CHECK_THAT(f.reason, Contains("did you mean 'density'?"));
    }
    SECTION("no hint when nothing is close") {
        const Failure f = failureOf(sceneWith(R"("environment": {"zzzzzz": 1})"));
        CHECK_THAT(f.reason, !Contains("did you mean"));
        CHECK_THAT(f.reason, Contains("expected one of: type, color"));
    }
}

TEST_CASE("wrong types say what was expected and what was found", "[scene]") {
    SECTION("string for a number") {
        const Failure f = failureOf(
            sceneWith(R"("lights": [{"type": "point", "position": [0, 1, 0], "intensity": "2"}])"));
        CHECK(f.message == R"(smoke.json:/lights/0/intensity: expected a number >= 0, got "2")");
    }
    SECTION("string for a colour") {
        const Failure f = failureOf(R"({"sources": [{"type": "sphere"}],
                          "materials": [{"name": "m", "absorption": "abc"}]})");
        CHECK(
            f.message ==
            R"(smoke.json:/materials/0/absorption: expected an array of 3 numbers >= 0, got "abc")");
    }
    SECTION("two numbers for a vec3") {
        const Failure f = failureOf(sceneWith(R"("camera": {"position": [1, 2]})"));
        CHECK(f.where == "smoke.json:/camera/position");
        CHECK_THAT(f.reason, Contains("expected an array of 3 numbers"));
        CHECK_THAT(f.reason, Contains("got [1,2]"));
    }
    SECTION("number for a boolean") {
        const Failure f = failureOf(sceneWith(R"("output": {"png": 1})"));
        CHECK(f.message == "smoke.json:/output/png: expected true or false, got 1");
    }
    SECTION("object for an array") {
        const Failure f = failureOf(R"({"sources": {"type": "sphere"}, "materials": []})");
        CHECK(f.where == "smoke.json:/sources");
        CHECK_THAT(f.reason, Contains("expected a non-empty array of sources"));
    }
    SECTION("fractional integer") {
        const Failure f = failureOf(sceneWith(R"("render": {"width": 320.5})"));
        CHECK(f.message ==
              "smoke.json:/render/width: expected an integer in [1, 16384], got 320.5");
    }
    SECTION("camera neither auto nor an object") {
        const Failure f = failureOf(sceneWith(R"("camera": "manual")"));
        CHECK(f.where == "smoke.json:/camera");
        CHECK_THAT(f.reason, Contains(R"(expected "auto" or an object)"));
        CHECK_THAT(f.reason, Contains(R"(got "manual")"));
    }
    SECTION("the document is not an object") {
        const Failure f = failureOf("[1, 2, 3]");
        CHECK(f.where == "smoke.json");
        CHECK_THAT(f.reason, Contains("expected the scene (an object), got [1,2,3]"));
    }
}

TEST_CASE("out-of-range values name the allowed range", "[scene]") {
    SECTION("negative intensity") {
        const Failure f = failureOf(
            sceneWith(R"("lights": [{"type": "point", "position": [0, 1, 0], "intensity": -1}])"));
        CHECK(f.message == "smoke.json:/lights/0/intensity: expected a number >= 0, got -1");
    }
    SECTION("g = 1") {
        const Failure f =
            failureOf(R"({"sources": [{"type": "sphere"}], "materials": [{"name": "m", "g": 1}]})");
        CHECK(f.message == "smoke.json:/materials/0/g: expected a number in (-1, 1), got 1");
    }
    SECTION("resolution 0") {
        const Failure f = failureOf(sceneWith(R"("volume": {"resolution": 0})"));
        CHECK(f.message ==
              "smoke.json:/volume/resolution: expected an integer in [1, 1024], got 0");
    }
    SECTION("one axis of a resolution array, at its own pointer") {
        const Failure f = failureOf(sceneWith(R"("volume": {"resolution": [64, 2000, 64]})"));
        CHECK(f.where == "smoke.json:/volume/resolution/1");
        CHECK_THAT(f.reason, Contains("expected an integer in [1, 1024], got 2000"));
    }
    SECTION("one negative colour channel, at its own pointer") {
        const Failure f = failureOf(sceneWith(R"("environment": {"color": [1, -0.5, 1]})"));
        CHECK(f.message == "smoke.json:/environment/color/1: expected a number >= 0, got -0.5");
    }
    SECTION("min_transmittance 1") {
        const Failure f = failureOf(sceneWith(R"("render": {"min_transmittance": 1})"));
        CHECK_THAT(f.reason, Contains("expected a number in [0, 1), got 1"));
    }
    SECTION("seed beyond uint32") {
        const Failure f = failureOf(sceneWith(R"("render": {"seed": 4294967296})"));
        CHECK(f.where == "smoke.json:/render/seed");
        CHECK_THAT(f.reason, Contains("expected an integer in [0, 4294967295]"));
    }
    SECTION("cone softness wider than the cone") {
        const Failure f = failureOf(sceneWith(
            R"("lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0],
                           "cone_angle_deg": 20, "cone_softness_deg": 25}])"));
        CHECK(f.where == "smoke.json:/lights/0/cone_softness_deg");
        CHECK_THAT(f.reason, Contains("expected a number in [0, 20] (at most cone_angle_deg)"));
    }
    SECTION("a disc on a point light, or wider than 30 degrees") {
        Failure f = failureOf(sceneWith(
            R"("lights": [{"type": "point", "position": [0, 1, 0], "angular_diameter_deg": 1}])"));
        CHECK(f.where == "smoke.json:/lights/0/angular_diameter_deg");
        CHECK_THAT(f.reason, Contains("a point light is a point"));
        f = failureOf(sceneWith(R"("lights": [{"type": "directional", "direction": [0, -1, 0],
                                              "angular_diameter_deg": 31}])"));
        CHECK(f.where == "smoke.json:/lights/0/angular_diameter_deg");
        CHECK_THAT(f.reason, Contains("expected a number in [0, 30]"));
    }
    SECTION("frame_end before frame_start") {
        const Failure f = failureOf(sceneWith(R"("time": {"frame_start": 5, "frame_end": 3})"));
        CHECK(f.message ==
              "smoke.json:/time/frame_end: expected an integer >= frame_start (5), got 3");
    }
    SECTION("bounds with min above max") {
        const Failure f =
            failureOf(sceneWith(R"("volume": {"bounds": {"min": [0, 0, 0], "max": [1, -1, 1]}})"));
        CHECK(f.where == "smoke.json:/volume/bounds/max");
        CHECK_THAT(f.reason, Contains("expected max > min on every axis"));
    }
    SECTION("a number too large for a float") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "sphere", "value": 1e300}], "materials": [{"name": "m"}]})");
        CHECK(f.where == "smoke.json:/sources/0/value");
        CHECK_THAT(f.reason, Contains("32-bit float"));
    }
    SECTION("an output name with a folder in it") {
        const Failure f = failureOf(sceneWith(R"("output": {"name": "renders/frame"})"));
        CHECK(f.where == "smoke.json:/output/name");
        CHECK_THAT(f.reason, Contains("without '/'"));
    }
    SECTION("a voxel size that would make a huge grid") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "sphere", "voxel_size": 1e-6}], "materials": [{"name": "m"}]})");
        CHECK(f.where == "smoke.json:/sources/0/voxel_size");
    }
}

TEST_CASE("a gladstone_dale material maps temperature to n below that of ambient air", "[scene]") {
    SECTION("the index slope and 1/T_ambient, with the default and a given ambient") {
        const eikon::Scene scene = eikon::parseScene(
            R"({"sources": [{"type": "sphere"}], "materials": [
                {"name": "air", "field": "temperature", "gladstone_dale": 0.00029},
                {"name": "hot", "field": "temperature", "gladstone_dale": 0.5,
                 "ambient_kelvin": 250}]})",
            "smoke.json");
        const eikon::MaterialSpec& air = scene.materials[0];
        CHECK(air.gladstoneDale == 0.00029f);
        CHECK(air.ambientKelvin == 288.15f);
        // ior − 1 is the slope at ambient; the exact map also needs 1/T_ambient
        // (tests/render/test_refraction.cpp checks n against the closed form).
        CHECK(air.ior == Approx(1.0 - 0.00029 / 288.15).epsilon(1e-7));
        CHECK(scene.materials[1].ior == Approx(1.0 - 0.5 / 250.0).epsilon(1e-7));
        CHECK(air.indexSlope() == Approx(-0.00029 / 288.15).epsilon(1e-6));
        CHECK(air.inverseAmbient() == Approx(1.0 / 288.15).epsilon(1e-7));
        CHECK(scene.materials[1].inverseAmbient() == Approx(1.0 / 250.0).epsilon(1e-7));
    }
    SECTION("ior and gladstone_dale together") {
        const Failure f = failureOf(R"({"sources": [{"type": "sphere"}], "materials": [
            {"name": "m", "ior": 1.5, "gladstone_dale": 0.1}]})");
        CHECK(f.where == "smoke.json:/materials/0/gladstone_dale");
        CHECK_THAT(f.reason, Contains("not both"));
    }
    SECTION("ambient_kelvin alone") {
        const Failure f = failureOf(R"({"sources": [{"type": "sphere"}], "materials": [
            {"name": "m", "ambient_kelvin": 300}]})");
        CHECK(f.where == "smoke.json:/materials/0/ambient_kelvin");
        CHECK_THAT(f.reason, Contains("needs \"gladstone_dale\""));
    }
    SECTION("a non-positive constant") {
        const Failure f = failureOf(R"({"sources": [{"type": "sphere"}], "materials": [
            {"name": "m", "gladstone_dale": 0}]})");
        CHECK(f.message == "smoke.json:/materials/0/gladstone_dale: expected a number > 0, got 0");
    }
}

TEST_CASE("a material's edge reflects (fresnel) unless it is hot air or marked graded", "[scene]") {
    const eikon::Scene scene = eikon::parseScene(
        R"({"sources": [{"type": "sphere"}], "materials": [
            {"name": "glass", "ior": 1.5},
            {"name": "grin", "field": "n", "ior": 2, "fresnel": false},
            {"name": "air", "field": "temperature", "gladstone_dale": 0.00029},
            {"name": "shocked", "field": "temperature", "gladstone_dale": 0.5, "fresnel": true}]})",
        "smoke.json");
    CHECK(scene.materials[0].fresnel);
    CHECK_FALSE(scene.materials[1].fresnel);
    CHECK_FALSE(scene.materials[2].fresnel);
    CHECK(scene.materials[3].fresnel);
    const Failure f = failureOf(R"({"sources": [{"type": "sphere"}], "materials": [
        {"name": "m", "ior": 1.5, "fresnel": "yes"}]})");
    CHECK(f.message == "smoke.json:/materials/0/fresnel: expected true or false, got \"yes\"");
}

TEST_CASE("view rays reflect at sharp surfaces unless render.fresnel is false", "[scene]") {
    const eikon::Scene plain = eikon::parseScene(sceneWith(R"("render": {})"), "smoke.json");
    CHECK(plain.render.fresnel);
    CHECK(plain.render.surfaceSlope == 0.01f);
    const eikon::Scene steeper = eikon::parseScene(
        sceneWith(R"("render": {"fresnel": true, "surface_slope": 0.05})"), "smoke.json");
    CHECK(steeper.render.surfaceSlope == 0.05f);
    CHECK_FALSE(eikon::parseScene(sceneWith(R"("render": {"fresnel": false})"), "smoke.json")
                    .render.fresnel);
    const Failure off =
        failureOf(sceneWith(R"("render": {"fresnel": false, "surface_slope": 0.05})"));
    CHECK(off.message ==
          "smoke.json:/render/surface_slope: \"surface_slope\" needs \"fresnel\": true");
    const Failure zero = failureOf(sceneWith(R"("render": {"surface_slope": 0})"));
    CHECK(zero.message == "smoke.json:/render/surface_slope: expected a number > 0, got 0");
}

TEST_CASE("missing required keys are reported where they belong", "[scene]") {
    SECTION("no sources") {
        const Failure f = failureOf(R"({"materials": [{"name": "m"}]})");
        CHECK(f.message ==
              "smoke.json:/sources: missing required key 'sources' (a non-empty array of sources)");
    }
    SECTION("empty materials") {
        const Failure f = failureOf(R"({"sources": [{"type": "sphere"}], "materials": []})");
        CHECK(f.message ==
              "smoke.json:/materials: expected a non-empty array of materials, got []");
    }
    SECTION("material without a name") {
        const Failure f = failureOf(R"({"sources": [{"type": "sphere"}], "materials": [{}]})");
        CHECK(f.where == "smoke.json:/materials/0/name");
        CHECK_THAT(f.reason, Contains("missing required key 'name'"));
    }
    SECTION("light without a type") {
        const Failure f = failureOf(sceneWith(R"("lights": [{"position": [0, 1, 0]}])"));
        CHECK(f.where == "smoke.json:/lights/0/type");
        CHECK_THAT(f.reason, Contains("missing required key 'type'"));
    }
    SECTION("spot light without a direction") {
        const Failure f =
            failureOf(sceneWith(R"("lights": [{"type": "spot", "position": [0, 1, 0]}])"));
        CHECK(f.where == "smoke.json:/lights/0/direction");
        CHECK_THAT(f.reason, Contains("missing required key 'direction'"));
    }
    SECTION("vdb source without a file") {
        const Failure f =
            failureOf(R"({"sources": [{"type": "vdb"}], "materials": [{"name": "m"}]})");
        CHECK(f.where == "smoke.json:/sources/0/file");
        CHECK_THAT(f.reason, Contains("missing required key 'file'"));
    }
}

TEST_CASE("enumerations list the allowed values", "[scene]") {
    SECTION("unknown light type") {
        const Failure f = failureOf(sceneWith(R"("lights": [{"type": "sunlight"}])"));
        CHECK(f.message == R"(smoke.json:/lights/0/type: expected one of "point", "directional", )"
                           R"("spot", got "sunlight")");
    }
    SECTION("close misspelling gets a hint") {
        const Failure f = failureOf(sceneWith(R"("lights": [{"type": "directonal"}])"));
        CHECK_THAT(f.reason, Contains(R"(did you mean "directional"?)"));
    }
    SECTION("unknown source type") {
        const Failure f =
            failureOf(R"({"sources": [{"type": "mesh"}], "materials": [{"name": "m"}]})");
        CHECK(f.where == "smoke.json:/sources/0/type");
        CHECK_THAT(f.reason, Contains(R"("vdb", "vdb_sequence", "scan", "sphere", "box")"));
    }
    SECTION("material on a field that is not canonical") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "sphere"}], "materials": [{"name": "m", "field": "densty"}]})");
        CHECK(f.where == "smoke.json:/materials/0/field");
        CHECK_THAT(f.reason, Contains(R"(did you mean "density"?)"));
    }
    SECTION("material on a vector field") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "sphere"}], "materials": [{"name": "m", "field": "velocity"}]})");
        CHECK(f.where == "smoke.json:/materials/0/field");
        CHECK_THAT(f.reason, Contains(R"(got "velocity")"));
    }
}

TEST_CASE("lights reject the keys their type has no use for", "[scene]") {
    SECTION("position on a directional light") {
        const Failure f = failureOf(sceneWith(
            R"("lights": [{"type": "directional", "direction": [0, -1, 0], "position": [0, 1, 0]}])"));
        CHECK(f.where == "smoke.json:/lights/0/position");
        CHECK_THAT(f.reason, Contains("a directional light has no position"));
    }
    SECTION("direction on a point light") {
        const Failure f = failureOf(sceneWith(
            R"("lights": [{"type": "point", "position": [0, 1, 0], "direction": [0, -1, 0]}])"));
        CHECK(f.where == "smoke.json:/lights/0/direction");
        CHECK_THAT(f.reason, Contains("a point light shines in every direction"));
    }
    SECTION("cone on a point light") {
        const Failure f = failureOf(sceneWith(
            R"("lights": [{"type": "point", "position": [0, 1, 0], "cone_angle_deg": 20}])"));
        CHECK(f.where == "smoke.json:/lights/0/cone_angle_deg");
        CHECK_THAT(f.reason, Contains("applies only to spot lights"));
    }
    SECTION("zero direction") {
        const Failure f =
            failureOf(sceneWith(R"("lights": [{"type": "directional", "direction": [0, 0, 0]}])"));
        CHECK(
            f.message ==
            "smoke.json:/lights/0/direction: expected a non-zero direction [x, y, z], got [0,0,0]");
    }
}

TEST_CASE("counts and uniqueness", "[scene]") {
    SECTION("too many lights") {
        const std::string light = R"({"type": "directional", "direction": [0, -1, 0]})";
        std::string lights = light;
        for (int i = 0; i < 4; ++i) lights += ", " + light;
        const Failure f = failureOf(sceneWith(R"("lights": [)" + lights + "]"));
        CHECK(f.message ==
              "smoke.json:/lights: expected at most 4 elements in an array of lights, "
              "got 5");
    }
    SECTION("too many materials") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "sphere"}], "materials": [{"name": "a"}, {"name": "b"},
                {"name": "c"}, {"name": "d"}, {"name": "e"}]})");
        CHECK(f.where == "smoke.json:/materials");
        CHECK_THAT(f.reason, Contains("at most 4"));
    }
    SECTION("duplicate material name") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "sphere"}], "materials": [{"name": "smoke"}, {"name": "smoke"}]})");
        CHECK(f.message ==
              "smoke.json:/materials/1/name: duplicate material name \"smoke\" "
              "(already used by /materials/0)");
    }
    SECTION("a key repeated in one object") {
        const Failure f = failureOf(sceneWith(R"("render": {"width": 320, "width": 640})"));
        CHECK(f.where == "smoke.json:/render/width");
        CHECK_THAT(f.reason, Contains("duplicate key 'width'"));
    }
    SECTION("a key repeated inside an array element") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "sphere"}, {"type": "box", "min": [0, 0, 0], "min": [1, 1, 1]}],
                "materials": [{"name": "m"}]})");
        CHECK(f.where == "smoke.json:/sources/1/min");
    }
}

TEST_CASE("camera geometry is checked", "[scene]") {
    SECTION("up parallel to the view direction") {
        const Failure f = failureOf(sceneWith(
            R"("camera": {"position": [0, 5, 0], "look_at": [0, 0, 0], "up": [0, 1, 0]})"));
        CHECK(f.where == "smoke.json:/camera/up");
        CHECK_THAT(f.reason, Contains("expected an up vector not parallel to the view direction"));
    }
    SECTION("default up parallel to the view direction") {
        const Failure f = failureOf(sceneWith(R"("camera": {"position": [0, -5, 0]})"));
        CHECK(f.where == "smoke.json:/camera/up");
        CHECK_THAT(f.reason, Contains("(the default)"));
    }
    SECTION("position equal to look_at") {
        const Failure f =
            failureOf(sceneWith(R"("camera": {"position": [1, 1, 1], "look_at": [1, 1, 1]})"));
        CHECK(f.where == "smoke.json:/camera/look_at");
        CHECK_THAT(f.reason, Contains("expected a point different from position"));
    }
    SECTION("field of view out of range") {
        const Failure f = failureOf(sceneWith(R"("camera": {"horizontal_fov_deg": 180})"));
        CHECK(f.message ==
              "smoke.json:/camera/horizontal_fov_deg: expected a number in (0, 180), got 180");
    }
}

TEST_CASE("syntax errors give the line and column", "[scene]") {
    const std::string text =
        "{\n  \"sources\": [],\n  \"materials\": [\n    {\"name\" \"m\"}\n  ]\n}";
    const Failure f = failureOf(text);
    CHECK(f.where == "smoke.json");
    // The column is where the parser stopped: the end of the unexpected "m" (columns 13-15).
    CHECK_THAT(f.reason, Contains("invalid JSON at line 4, column 15"));
    CHECK_THAT(f.reason, Contains("syntax error"));

    SECTION("a trailing comma") {
        const Failure trailing = failureOf("{\n  \"render\": {\"width\": 1,},\n}");
        CHECK_THAT(trailing.reason, Contains("line 2"));
    }
    SECTION("an empty file") {
        const Failure empty = failureOf("");
        CHECK_THAT(empty.reason, Contains("invalid JSON at line 1, column 1"));
    }
}

TEST_CASE("loadScene reports files it cannot read", "[scene]") {
    SECTION("missing file") {
        const std::string path = "no/such/scene.json";
        try {
            eikon::loadScene(path);
            FAIL("expected an error");
        } catch (const eikon::Error& e) {
            CHECK(e.where() == path);
            CHECK_THAT(e.reason(), Contains("not found"));
        }
    }
    SECTION("a folder") {
        REQUIRE_THROWS_WITH(eikon::loadScene(EIKON_SOURCE_DIR),
                            (Contains(EIKON_SOURCE_DIR) && Contains("is a folder")));
    }
    SECTION("errors in a loaded file name that file") {
        const fs::path folder = fs::path(EIKON_TEST_SCRATCH);
        fs::create_directories(folder);
        const fs::path path = folder / "bad_intensity.json";
        std::ofstream(path) << sceneWith(
            R"("lights": [{"type": "point", "position": [0, 1, 0], "intensity": -1}])");
        REQUIRE_THROWS_WITH(eikon::loadScene(path.string()),
                            Contains(path.string() + ":/lights/0/intensity"));
    }
}

TEST_CASE("relative source files resolve against the scene's folder", "[scene]") {
    const std::string text =
        R"({"sources": [{"type": "vdb", "file": "../caches/smoke.vdb"},
                        {"type": "vdb", "file": "/abs/smoke.vdb"}],
            "materials": [{"name": "m"}]})";
    const eikon::Scene scene = eikon::parseScene(text, "/projects/shot/scenes/smoke.json");
    CHECK(scene.sources[0].file == "/projects/shot/caches/smoke.vdb");
    CHECK(scene.sources[1].file == "/abs/smoke.vdb");

    SECTION("a #### pattern needs vdb_sequence") {
        const Failure f = failureOf(
            R"({"sources": [{"type": "vdb", "file": "smoke_####.vdb"}], "materials": [{"name": "m"}]})");
        CHECK(f.where == "smoke.json:/sources/0/file");
        CHECK_THAT(f.reason, Contains("vdb_sequence"));
    }
}

// The reader's helpers, through core/json_reader.h (the scene parser's building blocks).
TEST_CASE("json reader helpers", "[scene]") {
    using eikon::json::closestMatch;
    using eikon::json::editDistance;
    using eikon::json::Range;

    CHECK(editDistance("intesity", "intensity") == 1);
    CHECK(editDistance("widht", "width") == 1);  // a transposition is one edit
    CHECK(editDistance("", "abc") == 3);

    const std::vector<std::string> keys = {"min", "max", "horizontal_fov_deg", "g"};
    CHECK(closestMatch("maks", keys) == "max");
    CHECK(closestMatch("horizontalFovDeg", keys) == "horizontal_fov_deg");
    CHECK(closestMatch("G", keys) == "g");
    CHECK(closestMatch("x", keys).empty());  // one letter is no evidence of a typo
    CHECK(closestMatch("zzz", keys).empty());

    CHECK(Range::atLeast(0).describe() == ">= 0");
    CHECK(Range::greaterThan(0).describe() == "> 0");
    CHECK(Range::closedOpen(0, 1).describe() == "in [0, 1)");
    CHECK(Range::open(-1, 1).describe() == "in (-1, 1)");
    CHECK(Range::any().describe().empty());
    CHECK(Range::openClosed(0, 90).contains(90.0));
    CHECK_FALSE(Range::openClosed(0, 90).contains(0.0));

    CHECK(eikon::json::appendPointer("/aliases", "a/b~c") == "/aliases/a~1b~0c");
}

// ---- simulation ------------------------------------------------------------------------------

namespace {

const std::string kSimulation = R"("simulation": {
  "domain": {"min": [-1, 0, -1], "max": [1, 3, 1]},
  "resolution": 24,
  "walls": {"+y": "open", "-x": "closed"},
  "cfl": 2, "max_substeps": 16,
  "advection": "bfecc", "limiter": "clamp", "conserve_mass": true,
  "buoyancy_alpha": 0.05, "buoyancy_beta": 2, "ambient_temperature": 1,
  "vorticity": 1.5, "wind": [0.5, 0, 0],
  "pressure": {"tolerance": 1e-4, "max_iterations": 200, "preconditioner": "mic0"},
  "sources": [{"type": "sphere", "center": [0, 0.4, 0], "radius": 0.3, "density_rate": 3,
               "temperature_rate": 20, "velocity": [0, 1, 0], "velocity_rate": 10},
              {"type": "box", "min": [-1, 0, -1], "max": [1, 0.1, 1]}],
  "obstacles": [{"type": "sphere", "center": [0, 1.5, 0], "radius": 0.4},
                {"type": "box", "min": [0.5, 2, 0.5], "max": [1, 2.5, 1]}],
  "cache": "caches/plume"
})";

// sceneWith() plus a simulation section whose body is `body`.
std::string simulationWith(const std::string& body) {
    return sceneWith(R"("simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]},
                     "resolution": 16)" +
                     (body.empty() ? "" : ", " + body) + "}");
}

}  // namespace

TEST_CASE("a simulation section parses into the smoke settings", "[scene][simulation]") {
    SECTION("absent: no simulation") {
        CHECK(eikon::parseScene(sceneWith(""), "smoke.json").simulations.empty());
    }
    SECTION("every key") {
        const eikon::Scene scene = eikon::parseScene(
            sceneWith(kSimulation + R"(, "output": {"name": "plume"})"), "scenes/smoke.json");
        REQUIRE(scene.simulations.size() == 1);
        const eikon::SmokeSimulationSpec& sim = scene.simulations.at(0);
        // One integer: cells along the longest axis (y, 3 units), cubic cells elsewhere.
        CHECK(sim.voxelSize == Approx(0.125f));
        CHECK(sim.resolution == glm::ivec3(16, 24, 16));
        CHECK(sim.domain.max == glm::vec3(1, 3, 1));
        CHECK(sim.walls[3] == eikon::SimWall::Open);
        CHECK(sim.walls[0] == eikon::SimWall::Closed);
        CHECK(sim.walls[2] == eikon::SimWall::Closed);
        CHECK(sim.cfl == 2.0);
        CHECK(sim.maxSubsteps == 16);
        CHECK(sim.advection == eikon::SimAdvection::Bfecc);
        CHECK(sim.limiter == eikon::SimLimiter::Clamp);
        CHECK(sim.conserveMass);
        CHECK(sim.buoyancyAlpha == 0.05f);
        CHECK(sim.buoyancyBeta == 2.0f);
        CHECK(sim.ambientTemperature == 1.0f);
        CHECK(sim.vorticity == 1.5f);
        CHECK(sim.wind == glm::vec3(0.5f, 0, 0));
        CHECK(sim.pressureTolerance == 1e-4);
        CHECK(sim.pressureMaxIterations == 200);
        CHECK(sim.pressurePreconditioner == eikon::SimPreconditioner::Mic0);
        REQUIRE(sim.sources.size() == 2);
        CHECK(sim.sources[0].shape.kind == eikon::SimShapeSpec::Kind::Sphere);
        CHECK(sim.sources[0].shape.radius == 0.3f);
        CHECK(sim.sources[0].densityRate == 3.0f);
        CHECK(sim.sources[0].temperatureRate == 20.0f);
        CHECK(sim.sources[0].velocity == glm::vec3(0, 1, 0));
        CHECK(sim.sources[0].velocityRate == 10.0f);
        CHECK(sim.sources[1].shape.kind == eikon::SimShapeSpec::Kind::Box);
        CHECK(sim.sources[1].densityRate == 1.0f);  // the default
        REQUIRE(sim.obstacles.size() == 2);
        CHECK(sim.obstacles[1].boxMax == glm::vec3(1, 2.5f, 1));
        CHECK(sim.cacheDirectory == (fs::path("scenes") / "caches" / "plume").string());
        CHECK(sim.cacheName == "plume");  // from output.name
    }
    SECTION("defaults") {
        const eikon::Scene scene = eikon::parseScene(simulationWith(""), "smoke.json");
        REQUIRE(scene.simulations.size() == 1);
        const eikon::SmokeSimulationSpec& sim = scene.simulations.at(0);
        const eikon::SmokeSimulationSpec model;
        CHECK(sim.resolution == glm::ivec3(16));
        CHECK(sim.voxelSize == Approx(1.0f / 16));
        CHECK(sim.walls == model.walls);
        CHECK(sim.advection == eikon::SimAdvection::MacCormack);
        CHECK(sim.limiter == eikon::SimLimiter::Revert);
        CHECK_FALSE(sim.conserveMass);
        CHECK(sim.pressurePreconditioner == eikon::SimPreconditioner::Multigrid);
        CHECK(sim.sources.empty());
        CHECK(sim.obstacles.empty());
        CHECK(sim.cacheDirectory == "cache");
        CHECK(sim.cacheName == "smoke");  // no output.name
    }
    SECTION("three integers that give cubic cells") {
        const eikon::Scene scene = eikon::parseScene(
            sceneWith(R"("simulation": {"domain": {"min": [0, 0, 0], "max": [1, 2, 1]},
                         "resolution": [8, 16, 8]})"),
            "smoke.json");
        CHECK(scene.simulations.at(0).resolution == glm::ivec3(8, 16, 8));
        CHECK(scene.simulations.at(0).voxelSize == 0.125f);
    }
}

TEST_CASE("simulation mistakes name their JSON path", "[scene][simulation]") {
    SECTION("unknown key, with a hint") {
        const Failure f = failureOf(simulationWith(R"("vorticty": 2)"));
        CHECK(f.where == "smoke.json:/simulation/vorticty");
        CHECK_THAT(f.reason, Contains("did you mean 'vorticity'?"));
    }
    SECTION("unknown key in a source") {
        const Failure f =
            failureOf(simulationWith(R"("sources": [{"type": "sphere", "densty_rate": 2}])"));
        CHECK(f.where == "smoke.json:/simulation/sources/0/densty_rate");
        CHECK_THAT(f.reason, Contains("unknown key 'densty_rate' for a sphere smoke source"));
        CHECK_THAT(f.reason, Contains("did you mean 'density_rate'?"));
    }
    SECTION("wrong type") {
        const Failure f = failureOf(simulationWith(R"("cfl": "fast")"));
        CHECK(f.where == "smoke.json:/simulation/cfl");
        CHECK_THAT(f.reason, Contains("expected a number > 0"));
    }
    SECTION("wrong type of wall") {
        const Failure f = failureOf(simulationWith(R"("walls": {"+y": "opne"})"));
        CHECK(f.where == "smoke.json:/simulation/walls/+y");
        CHECK_THAT(f.reason, Contains("\"open\""));
    }
    SECTION("resolution out of range") {
        const Failure f = failureOf(sceneWith(
            R"("simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": 1000})"));
        CHECK(f.where == "smoke.json:/simulation/resolution");
        CHECK_THAT(f.reason, Contains("expected an integer in [2, 512], got 1000"));
    }
    SECTION("resolution element out of range") {
        const Failure f = failureOf(sceneWith(
            R"("simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": [16, 0, 16]})"));
        CHECK(f.where == "smoke.json:/simulation/resolution/1");
    }
    SECTION("resolution that does not give cubic cells") {
        const Failure f = failureOf(sceneWith(
            R"("simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": [16, 32, 16]})"));
        CHECK(f.where == "smoke.json:/simulation/resolution");
        CHECK_THAT(f.reason, Contains("cubes"));
    }
    SECTION("missing domain") {
        const Failure f = failureOf(sceneWith(R"("simulation": {"resolution": 16})"));
        CHECK(f.where == "smoke.json:/simulation/domain");
        CHECK_THAT(f.reason, Contains("missing required key 'domain'"));
    }
    SECTION("advection scheme") {
        const Failure f = failureOf(simulationWith(R"("advection": "mac_cormack")"));
        CHECK(f.where == "smoke.json:/simulation/advection");
        CHECK_THAT(f.reason, Contains("\"maccormack\""));
    }
    SECTION("inverted obstacle box") {
        const Failure f = failureOf(simulationWith(
            R"("obstacles": [{"type": "box", "min": [1, 1, 1], "max": [0, 0, 0]}])"));
        CHECK(f.where == "smoke.json:/simulation/obstacles/0/max");
    }
}

TEST_CASE("receivers parse with their defaults and name their mistakes", "[scene][receivers]") {
    SECTION("a floor with defaults and a wall with every key") {
        const eikon::Scene scene = eikon::parseScene(
            sceneWith(R"("receivers": [{"type": "plane", "axis": "y", "position": -0.5},
                {"type": "plane", "axis": "x", "position": 0.9, "facing": "-",
                 "albedo": [0.2, 0.4, 0.6], "method": "voxels", "texels_per_voxel": 4}])"),
            "smoke.json");
        REQUIRE(scene.receivers.size() == 2);
        const eikon::ReceiverSpec& floor = scene.receivers[0];
        CHECK(floor.axis == 1);
        CHECK(floor.position == -0.5f);
        CHECK(floor.facing == 1);
        CHECK(floor.albedo == glm::vec3(0.8f));
        CHECK(floor.method == eikon::ReceiverMethod::Plane);
        CHECK(floor.texelsPerVoxel == 2);
        CHECK(floor.jsonPath == "/receivers/0");
        const eikon::ReceiverSpec& wall = scene.receivers[1];
        CHECK(wall.axis == 0);
        CHECK(wall.facing == -1);
        CHECK(wall.albedo == glm::vec3(0.2f, 0.4f, 0.6f));
        CHECK(wall.method == eikon::ReceiverMethod::Voxels);
        CHECK(wall.texelsPerVoxel == 4);
    }
    SECTION("unknown key, with a hint") {
        const Failure f = failureOf(sceneWith(
            R"("receivers": [{"type": "plane", "axis": "y", "position": 0, "albdo": [1, 1, 1]}])"));
        CHECK(f.where == "smoke.json:/receivers/0/albdo");
        CHECK_THAT(f.reason, Contains("did you mean 'albedo'?"));
    }
    SECTION("albedo above 1") {
        const Failure f = failureOf(sceneWith(
            R"("receivers": [{"type": "plane", "axis": "y", "position": 0, "albedo": [1, 1.5, 1]}])"));
        CHECK(f.where == "smoke.json:/receivers/0/albedo/1");
    }
    SECTION("an axis that is not one") {
        const Failure f =
            failureOf(sceneWith(R"("receivers": [{"type": "plane", "axis": "w", "position": 0}])"));
        CHECK(f.where == "smoke.json:/receivers/0/axis");
        CHECK_THAT(f.reason, Contains("\"y\""));
    }
    SECTION("missing position") {
        const Failure f = failureOf(sceneWith(R"("receivers": [{"type": "plane", "axis": "y"}])"));
        CHECK(f.where == "smoke.json:/receivers/0/position");
    }
    SECTION("too many") {
        const std::string one = R"({"type": "plane", "axis": "y", "position": 0})";
        const Failure f = failureOf(sceneWith(R"("receivers": [)" + one + "," + one + "," + one +
                                              "," + one + "," + one + "]"));
        CHECK(f.where == "smoke.json:/receivers");
    }
}

TEST_CASE("render.light_transport is kept as written for the methods to read",
          "[scene][light_transport]") {
    // The methods and their settings live in render/ (render/light_transport_registry.h);
    // core keeps the section, in file order, and checks only that it is an object.
    const eikon::Scene set = eikon::parseScene(
        sceneWith(R"("render": {"light_transport": {"method": "photons", "photons": {"per_side": 64,
                  "stop_fraction": 0.5}}})"),
        "smoke.json");
    CHECK(set.render.lightTransport ==
          R"({"method":"photons","photons":{"per_side":64,"stop_fraction":0.5}})");
    const Failure f = failureOf(sceneWith(R"("render": {"light_transport": [1]})"));
    CHECK(f.where == "smoke.json:/render/light_transport");
    CHECK_THAT(f.reason, Contains("expected an object"));
}

TEST_CASE("the render keys that moved into render.light_transport say where they went",
          "[scene][light_transport]") {
    const Failure photons = failureOf(sceneWith(R"("render": {"photons": {"mode": "off"}})"));
    CHECK(photons.where == "smoke.json:/render/photons");
    CHECK_THAT(photons.reason, Contains("moved to render.light_transport"));
    CHECK_THAT(photons.reason, Contains("\"light_volumes\""));
    const Failure shadows = failureOf(sceneWith(R"("render": {"shadows": "marched"})"));
    CHECK(shadows.where == "smoke.json:/render/shadows");
    CHECK_THAT(shadows.reason, Contains("{\"light_volumes\": {\"shadows\": ...}}"));
    const Failure step = failureOf(sceneWith(R"("render": {"shadow_step_voxels": 2})"));
    CHECK(step.where == "smoke.json:/render/shadow_step_voxels");
    CHECK_THAT(step.reason, Contains("shadow_step_voxels"));
}
