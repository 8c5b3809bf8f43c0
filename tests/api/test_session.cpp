// The public C++ API (include/eikon/eikon.h, libeikon.so): the same pictures as the command line,
// byte for byte; simulations stepped and read as OpenVDB grids; camera, light, material and size
// changes between frames; errors as eikon::Error with the command line's one-line messages.
#include <catch2/catch.hpp>

#include <eikon/eikon.h>
#include <eikon/fields.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::scratchDir;
using eikon::test::sourcePath;

namespace {

const std::string kFog = sourcePath("data/scenes/glass_sphere_fog.json");
const std::string kSmoke = sourcePath("data/scenes/smoke_glass_mesh.json");

}  // namespace

TEST_CASE("a frame rendered by the library is the command line's PNG and EXR, byte for byte",
          "[api]") {
    const std::string dir = scratchDir("api_equals_cli");
    eikon::Session session = eikon::Session::open(kFog, eikon::Device::Cpu);
    session.setImageSize(48, 32);
    const eikon::RenderedImage image = session.render(0);
    REQUIRE(image.width == 48);
    REQUIRE(image.height == 32);
    REQUIRE(image.rgb.size() == 48 * 32 * 3);
    REQUIRE(image.srgb8.size() == 48 * 32 * 3);
    image.write(dir + "/lib.png");
    image.write(dir + "/lib.exr");
    const auto r = runEikon("render " + quoted(kFog) + " -o " + quoted(dir + "/cli.png") +
                                " --size 48x32 --backend cpu --exr --quiet",
                            dir);
    REQUIRE(r.exitCode == 0);
    CHECK(readFile(dir + "/lib.png") == readFile(dir + "/cli.png"));
    CHECK(readFile(dir + "/lib.exr") == readFile(dir + "/cli.exr"));
}

TEST_CASE("the live smoke stepped by the library reads as an OpenVDB density grid", "[api]") {
    eikon::Session session = eikon::Session::open(kSmoke, eikon::Device::Cpu);
    CHECK(session.firstFrame() == 1);
    session.stepTo(3);
    const auto names = eikon::fieldNames(session);
    CHECK(std::find(names.begin(), names.end(), "density") != names.end());
    const auto grid =
        openvdb::gridConstPtrCast<openvdb::FloatGrid>(eikon::fieldGrid(session, "density"));
    REQUIRE(grid);
    double mass = 0.0;
    for (auto it = grid->cbeginValueOn(); it; ++it) mass += double(*it);
    CHECK(mass > 0.0);
    // Stepping without rendering then rendering gives the picture of rendering directly.
    session.setImageSize(24, 24);
    const auto stepped = session.render(3);
    eikon::Session direct = eikon::Session::open(kSmoke, eikon::Device::Cpu);
    direct.setImageSize(24, 24);
    CHECK(direct.render(3).srgb8 == stepped.srgb8);
    CHECK_THROWS_WITH(eikon::fieldGrid(session, "smoke"),
                      Catch::StartsWith("field 'smoke': the session has no field"));
}

TEST_CASE("camera, lights, materials and size change between frames", "[api]") {
    eikon::Session session = eikon::Session::open(kFog, eikon::Device::Cpu);
    session.setImageSize(32, 24);
    const auto before = session.render(0);
    REQUIRE(session.lightCount() >= 1);
    eikon::Light light = session.light(0);
    light.intensity *= 2.0f;
    session.setLight(0, light);
    const auto brighter = session.render(0);
    double sumBefore = 0, sumAfter = 0;
    for (size_t i = 0; i < before.rgb.size(); ++i) {
        sumBefore += before.rgb[i];
        sumAfter += brighter.rgb[i];
    }
    CHECK(sumAfter > sumBefore);
    light.intensity /= 2.0f;
    session.setLight(0, light);
    CHECK(session.render(0).rgb == before.rgb);  // back as it was, exactly

    const std::vector<std::string> materials = session.materialNames();
    REQUIRE_FALSE(materials.empty());
    eikon::Material m = session.material(materials[0]);
    m.absorption = {m.absorption[0] + 3.0f, m.absorption[1] + 3.0f, m.absorption[2] + 3.0f};
    session.setMaterial(m);
    CHECK(session.render(0).rgb != before.rgb);

    eikon::Camera camera = session.camera();
    camera.horizontalFovDegrees = 20.0f;
    session.setCamera(camera);
    session.setImageSize(16, 12);
    const auto zoomed = session.render(0);
    CHECK(zoomed.width == 16);
    CHECK(zoomed.height == 12);

    CHECK_THROWS_AS(session.light(99), eikon::Error);
    CHECK_THROWS_WITH(session.material("glas"), Catch::Contains("no material of that name"));
    camera.horizontalFovDegrees = 180.0f;
    CHECK_THROWS_WITH(session.setCamera(camera), Catch::StartsWith("camera: "));
    CHECK_THROWS_AS(session.setImageSize(0, 10), eikon::Error);
}

TEST_CASE("a light's disc goes through the library, checked", "[api][soft_light]") {
    eikon::Session session = eikon::Session::open(kFog, eikon::Device::Cpu);
    eikon::Light light = session.light(0);
    CHECK(light.angularDiameterDegrees == 0.0f);
    light.kind = eikon::LightKind::Directional;
    light.angularDiameterDegrees = 31.0f;
    CHECK_THROWS_WITH(session.setLight(0, light),
                      Catch::Contains("angular_diameter_degrees must be in [0, 30]"));
    light.angularDiameterDegrees = 4.0f;
    session.setLight(0, light);
    CHECK(session.light(0).angularDiameterDegrees == 4.0f);
    light.kind = eikon::LightKind::Spot;
    CHECK_THROWS_AS(session.setLight(0, light), eikon::Error);
}

TEST_CASE("a material's dispersion reads and changes through the library", "[api][dispersion]") {
    eikon::Session session =
        eikon::Session::open(sourcePath("data/scenes/crystal_dispersion.json"), eikon::Device::Cpu);
    session.setImageSize(24, 18);
    const auto dispersed = session.render(0);
    eikon::Material flint = session.material("extra dense flint");
    CHECK(flint.ior == Approx(1.923f));
    CHECK(flint.abbe == Approx(20.9f));
    flint.abbe = 0.0f;  // one n in every channel
    session.setMaterial(flint);
    CHECK(session.render(0).rgb != dispersed.rgb);
    flint.abbe = 20.9f;
    session.setMaterial(flint);
    CHECK(session.render(0).rgb == dispersed.rgb);  // back as it was, exactly

    flint.abbe = -1.0f;
    CHECK_THROWS_WITH(session.setMaterial(flint),
                      Catch::StartsWith("material 'extra dense flint': abbe must be > 0"));
    flint.abbe = 20.9f;
    flint.ior = 1.0f;
    CHECK_THROWS_WITH(session.setMaterial(flint), Catch::Contains("ior above 1"));
    CHECK(session.material("extra dense flint").ior == Approx(1.923f));  // nothing changed
}

TEST_CASE("a material's transfer function reads and changes through the library",
          "[api][transfer]") {
    eikon::Session session =
        eikon::Session::open(sourcePath("data/scenes/ct_tooth.json"), eikon::Device::Cpu);
    session.setImageSize(16, 20);
    const auto classified = session.render(0);
    eikon::Material enamel = session.material("enamel");
    REQUIRE(enamel.transfer.size() == 3);
    CHECK(enamel.transfer[2][0] == Approx(0.85f));
    CHECK(enamel.transfer[2][1] == 1.0f);
    const auto kept = enamel.transfer;
    enamel.transfer.clear();  // the windowed scan itself: enamel everywhere the tooth is
    session.setMaterial(enamel);
    CHECK(session.render(0).rgb != classified.rgb);
    enamel.transfer = kept;
    session.setMaterial(enamel);
    CHECK(session.render(0).rgb == classified.rgb);  // back as it was, exactly

    enamel.transfer = {{0.0f, 0.0f}, {0.5f, 1.0f}, {0.4f, 2.0f}};
    CHECK_THROWS_WITH(session.setMaterial(enamel),
                      Catch::StartsWith("material 'enamel': the transfer function point 2: value "
                                        "0.4 is not above the one before, 0.5"));
    enamel.transfer = {{0.0f, 1.0f}, {1.0f, 1.0f}};
    CHECK_THROWS_WITH(session.setMaterial(enamel), Catch::Contains("maps 0 to 1"));
    CHECK(session.material("enamel").transfer.size() == 3);  // nothing changed
}

TEST_CASE("bad scenes and files are eikon::Error with the command line's messages", "[api]") {
    // The fog scene as text, its first light's intensity made negative.
    std::string text = readFile(kFog);
    const size_t at = text.find("\"intensity\":");
    REQUIRE(at != std::string::npos);
    text.insert(at + 12, " -1, \"was\":");
    try {
        eikon::Session::fromJson(text, "/tmp", eikon::Device::Cpu);
        FAIL("no error");
    } catch (const eikon::Error& e) {
        CHECK(std::string(e.what()).rfind("/tmp/<json text>:/lights/0/intensity: ", 0) == 0);
    }
    CHECK_THROWS_WITH(eikon::Session::open("/nonexistent/scene.json", eikon::Device::Cpu),
                      Catch::StartsWith("/nonexistent/scene.json: "));
}

TEST_CASE("fields written by the library read back through the checked reader", "[api]") {
    const std::string dir = scratchDir("api_fields");
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->tree().setValue({1, 2, 3}, 0.5f);
    eikon::writeFields(dir + "/a.vdb", {density});
    const openvdb::GridPtrVec back = eikon::readFields(dir + "/a.vdb");
    REQUIRE(back.size() == 1);
    const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(back[0]);
    REQUIRE(grid);
    CHECK(grid->tree().getValue({1, 2, 3}) == 0.5f);
    // Cut in half: an error, not a grid of zeros.
    const std::string bytes = readFile(dir + "/a.vdb");
    std::ofstream(dir + "/cut.vdb", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    CHECK_THROWS_AS(eikon::readFields(dir + "/cut.vdb"), eikon::Error);
}
