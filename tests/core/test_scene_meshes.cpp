// The scene's "meshes" array (core/scene_meshes.h): what it makes of a mesh, and every error it
// promises, each at its JSON pointer.
#include <catch2/catch.hpp>

#include <string>

#include <glm/geometric.hpp>

#include "core/animation_targets.h"
#include "core/error.h"
#include "core/mesh_placement.h"
#include "core/scene.h"

using namespace eikon;

namespace {

Scene parseMeshes(const std::string& meshes, const std::string& extra = "") {
    return parseScene(R"({"meshes": )" + meshes + extra + "}", "m.json");
}

}  // namespace

TEST_CASE("a mesh carries its optics as materials over its own two fields", "[scene][meshes]") {
    const Scene scene = parseMeshes(R"([{"name": "glass", "file": "glass.obj", "ior": 1.5,
        "absorption": [0.1, 0.2, 0.3], "g": 0.3, "translate": [1, 2, 3], "scale": 2,
        "rotate_deg": [0, 90, 0], "close_holes": 12, "blur": {"sigma_voxels": 1, "radius_voxels": 3}}])");
    REQUIRE(scene.meshes.size() == 1);
    const MeshObjectSpec& m = scene.meshes[0];
    CHECK(m.file == "glass.obj");
    CHECK(m.closeHolesUpTo == 12);
    CHECK(m.scale == glm::vec3(2.0f));
    CHECK(m.blurRadiusVoxels == 3);
    CHECK(scene.sources.empty());
    REQUIRE(scene.materials.size() == 2);
    CHECK(scene.materials[0].name == "glass");
    CHECK(scene.materials[0].field == "mesh:glass");
    CHECK(scene.materials[0].ior == 1.0f);
    CHECK(scene.materials[0].g == 0.3f);
    CHECK(scene.materials[1].name == "glass.n");
    CHECK(scene.materials[1].field == "mesh:glass:n");
    CHECK(scene.materials[1].ior == 1.5f);
    CHECK(meshOfField(scene, "mesh:glass:n") == 0);
    CHECK(meshOfField(scene, "density") == -1);
    // Scale, then rotate 90° about y (x → −z), then translate.
    TriangleMesh point;
    point.positions = {glm::vec3(1.0f, 0.0f, 0.0f)};
    const glm::vec3 p = placeMesh(point, m).positions[0];
    CHECK(glm::length(p - glm::vec3(1.0f, 2.0f, 1.0f)) < 1e-5f);
    CHECK(placePoint(point.positions[0], m) == p);
    // A world motion undone into object space: the object-space step lands the placed point
    // exactly that far in the world (x → −z, halved by the scale).
    const glm::vec3 motion(0.3f, -0.2f, 0.5f);
    const glm::vec3 local = unplaceMotion(motion, m);
    CHECK(glm::length(local - glm::vec3(-0.25f, -0.1f, 0.15f)) < 1e-6f);
    CHECK(glm::length(placePoint(point.positions[0] + local, m) - (p + motion)) < 1e-5f);
}

TEST_CASE("shapes make closed meshes, a quaternion rotation is read in glTF order",
          "[scene][meshes]") {
    const Scene scene = parseMeshes(R"([
        {"name": "a", "shape": {"type": "icosphere", "radius": 0.25, "subdivisions": 2}, "ior": 2.4},
        {"name": "b", "shape": {"type": "box", "min": [0, 0, 0], "max": [1, 2, 3]},
         "rotation": [0, 0, 0.7071068, 0.7071068], "scattering": [1, 1, 1]}])");
    CHECK(meshShape(scene.meshes[0]).triangles.size() == 320);
    CHECK(signedVolume(meshShape(scene.meshes[1])) == Approx(6.0));
    // 90° about z: x → y.
    TriangleMesh point;
    point.positions = {glm::vec3(1.0f, 0.0f, 0.0f)};
    CHECK(glm::length(placeMesh(point, scene.meshes[1]).positions[0] - glm::vec3(0, 1, 0)) < 1e-5f);
    CHECK(scene.materials.size() == 2);  // a.n, b
}

TEST_CASE("a liquid takes its container's placement, now and when it is animated",
          "[scene][meshes]") {
    Scene scene = parseMeshes(R"([
        {"name": "glass", "file": "g.obj", "ior": 1.5, "translate": [1, 2, 3], "scale": 0.5,
         "rotate_deg": [0, 90, 0]},
        {"name": "wine", "shape": {"type": "liquid", "container": "glass", "fill": 0.25},
         "ior": 1.34, "absorption": [0.2, 2, 2]}])");
    REQUIRE(scene.meshes.size() == 2);
    const MeshObjectSpec& wine = scene.meshes[1];
    CHECK(wine.shape == MeshShapeType::Liquid);
    CHECK(wine.container == 0);
    CHECK(wine.fill == 0.25);
    CHECK(&placementOf(scene, 1) == &scene.meshes[0]);
    CHECK(&placementOf(scene, 0) == &scene.meshes[0]);
    CHECK(meshShape(wine).triangles.empty());  // made from the container by the driver

    // Animating the container moves the liquid: both are placed by the container's spec.
    std::string why;
    const auto target = resolveAnimationTarget(scene, "/meshes/0/translate", why);
    REQUIRE(target);
    const float moved[3] = {4.0f, 5.0f, 6.0f};
    writeAnimationTarget(scene, *target, moved);
    const TriangleMesh point{{glm::vec3(0.0f)}, {}};
    CHECK(placeMesh(point, placementOf(scene, 1)).positions[0] == glm::vec3(4.0f, 5.0f, 6.0f));
}

TEST_CASE("mesh errors name the key and say what was expected", "[scene][meshes]") {
    auto fails = [](const std::string& meshes, const std::string& where, const std::string& what,
                    const std::string& extra = "") {
        INFO(meshes);
        CHECK_THROWS_WITH(parseMeshes(meshes, extra),
                          Catch::Contains("m.json:" + where) && Catch::Contains(what));
    };
    fails(
        R"([{"name": "x", "file": "a.obj", "shape": {"type": "box", "min": [0,0,0], "max": [1,1,1]}, "ior": 1.5}])",
        "/meshes/0/shape", "either \"file\" or \"shape\"");
    fails(R"([{"name": "x", "ior": 1.5}])", "/meshes/0/file", "needs \"file\" or \"shape\"");
    fails(R"([{"name": "x", "file": "a.obj"}])", "/meshes/0", "a mesh needs optics");
    fails(R"([{"name": "x", "file": "a.obj", "ior": 0.9}])", "/meshes/0/ior", ">= 1");
    fails(
        R"([{"name": "x", "file": "a.obj", "ior": 1.5}, {"name": "x", "file": "b.obj", "ior": 1.5}])",
        "/meshes/1/name", "duplicate mesh name");
    fails(R"([{"name": "a b", "file": "a.obj", "ior": 1.5}])", "/meshes/0/name", "letters");
    fails(
        R"([{"name": "x", "shape": {"type": "box", "min": [0,0,0], "max": [1,0,1]}, "ior": 1.5}])",
        "/meshes/0/shape/max", "max > min");
    fails(R"([{"name": "x", "shape": {"type": "cone"}, "ior": 1.5}])", "/meshes/0/shape/type",
          "icosphere");
    fails(
        R"([{"name": "x", "shape": {"type": "icosphere", "radius": 1}, "close_holes": 3, "ior": 1.5}])",
        "/meshes/0/close_holes", "from a file");
    fails(R"([{"name": "x", "file": "a.obj", "rotation": [0, 0, 0.5, 0.5], "ior": 1.5}])",
          "/meshes/0/rotation", "unit quaternion");
    fails(R"([{"name": "x", "file": "a.obj", "ior": 1.5, "scale": [1, 0, 1]}])",
          "/meshes/0/scale/1", "> 0");
    fails(R"([{"name": "x", "file": "a.obj", "ior": 1.5, "blur": {"radius": 2}}])",
          "/meshes/0/blur/radius", "unknown key");
    fails(R"([{"name": "x", "file": "a.obj", "ior": 1.5, "transalte": [0, 0, 0]}])",
          "/meshes/0/transalte", "translate");
    // Two meshes with colour and index take four slots; one more material is one too many.
    fails(R"([{"name": "a", "file": "a.obj", "ior": 1.5, "absorption": [1,1,1]},
              {"name": "b", "file": "b.obj", "ior": 1.5, "absorption": [1,1,1]}])",
          "/meshes", "exceed 4 material slots",
          R"(, "sources": [{"type": "sphere", "field": "density", "radius": 1}],
              "materials": [{"name": "smoke", "field": "density", "scattering": [1,1,1]}])");
    fails(R"([{"name": "smoke", "file": "a.obj", "ior": 1.5}])", "/meshes/0/name",
          "clashes with material",
          R"(, "sources": [{"type": "sphere", "field": "density", "radius": 1}],
              "materials": [{"name": "smoke", "field": "density", "scattering": [1,1,1]}])");
    fails(R"([{"name": "w", "shape": {"type": "water", "size": [2, 2], "depth": 0.3,
              "droplets": [{"time": 0, "position": [1.5, 0]}]}, "ior": 1.33}])",
          "/meshes/0/shape/droplets/0/position/0", "in [-1, 1]");
    fails(R"([{"name": "w", "shape": {"type": "water", "size": [2, 2]}, "ior": 1.33}])",
          "/meshes/0/shape/depth", "missing required key");
    fails(R"([{"name": "w", "shape": {"type": "water", "size": [2, 2], "depth": 0.3}, "ior": 1.33,
              "deformer": {"type": "jelly"}}])",
          "/meshes/0/deformer", "takes no deformer");
    fails(R"([{"name": "j", "shape": {"type": "icosphere", "radius": 1}, "ior": 1.4,
              "deformer": {"type": "jelly", "stiffnes": 3}}])",
          "/meshes/0/deformer/stiffnes", "stiffness");
    fails(R"([{"name": "j", "shape": {"type": "icosphere", "radius": 1}, "ior": 1.4,
              "deformer": {"type": "jelly", "pokes": [{"time": 1, "position": [0, 0, 0]}]}}])",
          "/meshes/0/deformer/pokes/0", "velocity");
    fails(
        R"([{"name": "j", "shape": {"type": "icosphere", "radius": 1}, "ior": 1.4,
              "deformer": {"type": "jelly"}}])",
        "/animation/0/target", "moves by its own simulation",
        R"(, "animation": [{"target": "/meshes/0/translate", "times": [0], "values": [[0, 0, 0]]}])");
    const std::string glass = R"({"name": "glass", "file": "g.obj", "ior": 1.5})";
    fails(
        "[" + glass +
            R"(, {"name": "w", "shape": {"type": "liquid", "container": "cup", "fill": 0.5}, "ior": 1.33}])",
        "/meshes/1/shape/container", "no earlier mesh is named \"cup\"");
    fails(
        R"([{"name": "w", "shape": {"type": "liquid", "container": "glass", "fill": 0.5}, "ior": 1.33}, )" +
            glass + "]",
        "/meshes/0/shape/container", "must come before it");
    fails(
        "[" + glass +
            R"(, {"name": "w", "shape": {"type": "liquid", "container": "glass", "fill": 1.2}, "ior": 1.33}])",
        "/meshes/1/shape/fill", "(0, 1]");
    fails("[" + glass +
              R"(, {"name": "w", "shape": {"type": "liquid", "container": "glass"}, "ior": 1.33}])",
          "/meshes/1/shape/fill", "missing required key");
    fails("[" + glass +
              R"(, {"name": "w", "shape": {"type": "liquid", "container": "glass", "fill": 0.5},
              "translate": [0, 1, 0], "ior": 1.33}])",
          "/meshes/1/translate", "container's placement");
    fails(R"([{"name": "p", "shape": {"type": "water", "size": [2, 2], "depth": 0.3}, "ior": 1.33},
              {"name": "w", "shape": {"type": "liquid", "container": "p", "fill": 0.5}, "ior": 1.33}])",
          "/meshes/1/shape/container", "not a container");
    fails(
        R"([{"name": "j", "shape": {"type": "icosphere", "radius": 1}, "ior": 1.4, "deformer": {"type": "jelly"}},
              {"name": "w", "shape": {"type": "liquid", "container": "j", "fill": 0.5}, "ior": 1.33}])",
        "/meshes/1/shape/container", "deforming container");
    fails(
        "[" + glass +
            R"(, {"name": "w", "shape": {"type": "liquid", "container": "glass", "fill": 0.5}, "ior": 1.33}])",
        "/animation/0/target", "moves with its container 'glass'",
        R"(, "animation": [{"target": "/meshes/1/translate", "times": [0], "values": [[0, 0, 0]]}])");
    const std::string handles =
        R"("handles": [{"name": "base", "box": {"min": [-1, -1, -1], "max": [1, -0.5, 1]}},
                                  {"name": "top", "sphere": {"center": [0, 1, 0], "radius": 0.3}}])";
    const std::string arap =
        R"([{"name": "j", "shape": {"type": "icosphere", "radius": 1}, "ior": 1.4,
              "deformer": {"type": "arap", )";
    fails(arap + R"("handles": []}}])", "/meshes/0/deformer/handles", "at least one handle");
    fails(arap + R"("handles": [{"name": "h"}]}}])", "/meshes/0/deformer/handles/0/sphere",
          "needs a region");
    fails(arap + R"("handles": [{"name": "h", "sphere": {"center": [0, 0, 0], "radius": 1},
              "box": {"min": [0, 0, 0], "max": [1, 1, 1]}}]}}])",
          "/meshes/0/deformer/handles/0/box", "not both");
    fails(arap + R"("handles": [{"name": "h", "sphere": {"center": [0, 0, 0], "radius": 0}}]}}])",
          "/meshes/0/deformer/handles/0/sphere/radius", "> 0");
    fails(arap + R"("handles": [{"name": "h", "sphere": {"center": [0, 0, 0], "radius": 1}},
              {"name": "h", "sphere": {"center": [0, 1, 0], "radius": 1}}]}}])",
          "/meshes/0/deformer/handles/1/name", "duplicate handle name");
    fails(arap + R"("iterations": 0, )" + handles + "}}]", "/meshes/0/deformer/iterations", "1");
    fails(
        arap + handles + "}}]", "/animation/0/target", "has no handle 2",
        R"(, "animation": [{"target": "/meshes/0/deformer/handles/2/translate", "times": [0], "values": [[0, 0, 0]]}])");
    fails(
        arap + handles + "}}]", "/animation/0/target", "translate or rotation, not 'scale'",
        R"(, "animation": [{"target": "/meshes/0/deformer/handles/1/scale", "times": [0], "values": [[1, 1, 1]]}])");
    fails(
        R"([{"name": "g", "file": "g.obj", "ior": 1.5}])", "/animation/0/target",
        "has no ARAP deformer",
        R"(, "animation": [{"target": "/meshes/0/deformer/handles/0/translate", "times": [0], "values": [[0, 0, 0]]}])");
    fails(arap + handles + "}}]", "/simulation/obstacles/0/mesh", "dragged by ARAP handles",
          R"(, "simulation": {"domain": {"min": [-2, -2, -2], "max": [2, 2, 2]}, "resolution": 8,
              "obstacles": [{"mesh": "j"}]})");
    {
        Scene s = parseMeshes(arap + handles + "}}]",
                              R"(, "animation": [{"target": "/meshes/0/deformer/handles/1/rotation",
                                  "times": [0], "values": [[0, 0, 1, 0]]}])");
        REQUIRE(s.meshes[0].arap);
        const ArapSpec& a = *s.meshes[0].arap;
        CHECK(a.iterations == 5);
        REQUIRE(a.handles.size() == 2);
        CHECK_FALSE(a.handles[0].sphere);
        CHECK(a.handles[0].center == glm::vec3(0.0f, -0.75f, 0.0f));  // a box's pivot: its centre
        CHECK(a.handles[1].radius == 0.3f);
        std::string why;
        const auto t = resolveAnimationTarget(s, "/meshes/0/deformer/handles/1/rotation", why);
        REQUIRE(t);
        CHECK(t->rotation);
        const float q[4] = {0.0f, 0.0f, 2.0f, 0.0f};  // normalized when written
        writeAnimationTarget(s, *t, q);
        CHECK(s.meshes[0].arap->handles[1].rotation == glm::quat(0.0f, 0.0f, 0.0f, 1.0f));
    }
    // Without meshes, sources and materials stay required.
    CHECK_THROWS_WITH(parseScene("{}", "m.json"),
                      Catch::Contains("missing required key 'sources'"));
}

TEST_CASE("a smoke obstacle names a mesh that stands still, or the error says why",
          "[scene][meshes][simulation]") {
    const std::string meshes = R"([
        {"name": "glass", "shape": {"type": "icosphere", "radius": 0.2}, "ior": 1.5},
        {"name": "blob", "shape": {"type": "icosphere", "radius": 0.2}, "ior": 1.4,
         "deformer": {"type": "jelly"}},
        {"name": "pool", "shape": {"type": "water", "size": [1, 1], "depth": 0.2}, "ior": 1.33}])";
    auto scene = [&](const std::string& obstacle, const std::string& animation = "") {
        return R"(, "simulation": {"domain": {"min": [-1, 0, -1], "max": [1, 2, 1]},
            "resolution": 8, "obstacles": [{"type": "sphere"}, )" +
               obstacle + "]}" + animation;
    };
    const Scene ok = parseMeshes(meshes, scene(R"({"mesh": "glass"})"));
    REQUIRE(ok.simulations.at(0).obstacles.size() == 2);
    CHECK(ok.simulations.at(0).obstacles[1].kind == SimShapeSpec::Kind::Mesh);
    CHECK(ok.simulations.at(0).obstacles[1].mesh == 0);
    CHECK(ok.simulations.at(0).obstacles[1].jsonPath == "/simulation/obstacles/1");
    // Animating the glass's optics moves nothing: still an obstacle.
    CHECK_NOTHROW(parseMeshes(meshes, scene(R"({"mesh": "glass"})",
                                            R"(, "animation": [{"target": "/meshes/0/ior",
                                               "times": [0, 1], "values": [1.5, 1.6]}])")));

    auto fails = [&](const std::string& text, const std::string& where, const std::string& what) {
        INFO(text);
        CHECK_THROWS_WITH(parseMeshes(meshes, text),
                          Catch::Contains("m.json:" + where) && Catch::Contains(what));
    };
    fails(scene(R"({"mesh": "glas"})"), "/simulation/obstacles/1/mesh",
          "no mesh named 'glas' in \"meshes\" (it has 'glass', 'blob', 'pool')");
    fails(scene(R"({"mesh": "blob"})"), "/simulation/obstacles/1/mesh",
          "mesh 'blob' moves by its own simulation (jelly); a smoke obstacle must stand still");
    fails(scene(R"({"mesh": "pool"})"), "/simulation/obstacles/1/mesh",
          "mesh 'pool' moves by its own simulation (water)");
    fails(scene(R"({"mesh": "glass", "type": "box"})"), "/simulation/obstacles/1/type",
          "unknown key 'type' for a mesh obstacle");
    fails(scene(R"({"mesh": "glass"})", R"(, "lights": [{"type": "point", "position": [0, 2, 0]}],
              "animation": [{"target": "/lights/0/intensity", "times": [0], "values": [1]},
              {"target": "/meshes/0/translate", "times": [0, 1],
               "values": [[0, 0, 0], [0, 1, 0]]}])"),
          "/simulation/obstacles/1/mesh",
          "mesh 'glass' is moved by /animation/1 (/meshes/0/translate); a smoke obstacle must "
          "stand still");
    CHECK_THROWS_WITH(parseScene(R"({"sources": [{"type": "sphere", "field": "density"}],
            "materials": [{"name": "smoke", "scattering": [1, 1, 1]}],
            "simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": 8,
            "obstacles": [{"mesh": "glass"}]}})",
                                 "n.json"),
                      Catch::Contains("n.json:/simulation/obstacles/0/mesh") &&
                          Catch::Contains("the scene has none"));
}

TEST_CASE("a VDB file among the meshes is a level set, its grid chosen by name or index",
          "[scene][meshes][level_set]") {
    const Scene scene = parseMeshes(R"([
        {"name": "ball", "file": "ball.vdb", "ior": 1.5, "translate": [0, 1, 0]},
        {"name": "named", "file": "shapes.VDB", "grid": "surface", "absorption": [1, 1, 1]},
        {"name": "nano", "file": "shapes.nvdb", "grid": 2, "ior": 1.33}])");
    REQUIRE(scene.meshes.size() == 3);
    CHECK(scene.meshes[0].shape == MeshShapeType::LevelSet);
    CHECK_FALSE(scene.meshes[0].grid.given());
    CHECK(scene.meshes[1].shape == MeshShapeType::LevelSet);
    CHECK(scene.meshes[1].grid.name == "surface");
    CHECK(scene.meshes[2].grid.index == 2);
    CHECK(meshShape(scene.meshes[0]).triangles.empty());
    // The same optics as a triangle mesh's: the index over the blurred coverage.
    CHECK(scene.materials[0].field == "mesh:ball:n");
    CHECK(scene.materials[0].ior == 1.5f);

    auto fails = [](const std::string& meshes, const std::string& where, const std::string& what) {
        INFO(meshes);
        CHECK_THROWS_WITH(parseMeshes(meshes),
                          Catch::Contains("m.json:" + where) && Catch::Contains(what));
    };
    fails(R"([{"name": "x", "file": "a.obj", "grid": 0, "ior": 1.5}])", "/meshes/0/grid",
          "picks a level set's grid in a VDB file; a.obj is not one");
    fails(R"([{"name": "x", "file": "a.vdb", "grid": -1, "ior": 1.5}])", "/meshes/0/grid", "0");
    fails(R"([{"name": "x", "file": "a.vdb", "grid": "", "ior": 1.5}])", "/meshes/0/grid",
          "non-empty");
    fails(R"([{"name": "x", "file": "a.vdb", "close_holes": 2, "ior": 1.5}])",
          "/meshes/0/close_holes", "a level set is closed");
    fails(R"([{"name": "x", "file": "a.vdb", "ior": 1.5,
               "deformer": {"type": "jelly"}}])",
          "/meshes/0/deformer", "a level set takes no deformer");
    fails(R"([{"name": "x", "file": "a.vdb", "ior": 1.5},
              {"name": "w", "shape": {"type": "liquid", "container": "x", "fill": 0.5}, "ior": 1.33}])",
          "/meshes/1/shape/container", "is a level set, not a container");
}
