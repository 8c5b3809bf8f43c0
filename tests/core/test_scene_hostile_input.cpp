// Scene files made to break the parser (issue 14): numbers beyond a double, nesting 100,000 deep,
// control characters in names, domains 1e-30 wide. Each must be one eikon::Error naming the file
// and, where there is one, the JSON pointer; before, they gave "internal error: [json.exception.
// out_of_range.406] ...", bad_alloc, a name cut at its NUL, and "internal error: ArithmeticError:
// Non-zero scale values required".
#include <catch2/catch.hpp>

#include <string>

#include "core/error.h"
#include "core/printable.h"
#include "core/scene.h"
#include "support/test_paths.h"

namespace {

const std::string kMinimalBody = R"("sources": [{"type": "sphere"}], "materials": [{"name": "m"}])";

std::string sceneWith(const std::string& extraKeys) {
    return "{" + kMinimalBody + ", " + extraKeys + "}";
}

// The error parsing `text` as smoke.json raises, as "<where>: <reason>".
std::string errorOf(const std::string& text) {
    try {
        eikon::parseScene(text, "smoke.json");
    } catch (const eikon::Error& e) {
        return e.what();
    }
    FAIL("expected an eikon::Error");
    return {};
}

// The error loading the fuzzing regression input `name` (tests/fuzz/regressions/scene/), as
// eikon render loads a scene; it must be one printable line.
std::string regressionError(const std::string& name) {
    const std::string path = eikon::test::sourcePath("tests/fuzz/regressions/scene/" + name);
    try {
        eikon::loadScene(path);
    } catch (const eikon::Error& e) {
        INFO(e.what());
        CHECK_FALSE(eikon::hasControlCharacter(e.what()));
        return std::string(e.what()).substr(path.size());
    }
    FAIL("expected an eikon::Error");
    return {};
}

}  // namespace

TEST_CASE("printable() escapes control characters and cuts long text", "[scene][json]") {
    CHECK(eikon::printable(std::string("a\0b\x1b[2J\r\n\t\x7f", 11)) ==
          "a\\x00b\\x1b[2J\\r\\n\\t\\x7f");
    CHECK(eikon::printable("caf\xc3\xa9") == "caf\xc3\xa9");  // UTF-8 stays
    CHECK(eikon::printable(std::string(100, 'x'), 10) == std::string(10, 'x') + "...");
}

TEST_CASE("a JSON number beyond a double names the file and the pointer", "[scene][json]") {
    CHECK(errorOf(sceneWith(R"("render": {"width": 1e400})")) ==
          "smoke.json:/render/width: the number 1e400 is out of range (a double reaches about "
          "1.8e308)");
    CHECK(errorOf(sceneWith(R"("volume": {"bounds": {"min": [0, -1e400, 0], "max": [1, 1, 1]}})"))
              .rfind("smoke.json:/volume/bounds/min/1: the number -1e400 is out of range", 0) == 0);
}

TEST_CASE("JSON nested deeper than 256 levels is an error, not bad_alloc", "[scene][json]") {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    const std::string error = errorOf(deep);
    CHECK(error.rfind("smoke.json: nested deeper than 256 arrays and objects (at /0/0/0/", 0) == 0);
    CHECK(error.size() < 200);
    // 200 levels is within the limit: the scene's own check speaks (the root is not an object).
    const std::string ok = std::string(200, '[') + std::string(200, ']');
    CHECK(errorOf(ok).find("nested") == std::string::npos);
}

TEST_CASE("control characters in scene strings are refused at their pointer", "[scene][json]") {
    // A NUL in output.name cut every later message short and made cleanup rmdir the output folder.
    CHECK(
        errorOf(sceneWith(R"("output": {"name": "a\u0000b"})")) ==
        R"(smoke.json:/output/name: expected a string without control characters, got "a\u0000b")");
    CHECK(
        errorOf(sceneWith(R"("output": {"directory": "out\u001b[2J"})")) ==
        R"(smoke.json:/output/directory: expected a string without control characters, got "out\u001b[2J")");
    // Keys are echoed escaped, in the reason and in the pointer.
    CHECK(errorOf(sceneWith(R"("ren\u0007der": 1)"))
              .rfind("smoke.json:/ren\\x07der: unknown key 'ren\\x07der'", 0) == 0);
}

TEST_CASE("voxels too small for OpenVDB or float precision are refused when read",
          "[scene][json]") {
    CHECK(
        errorOf(sceneWith(
            R"("volume": {"bounds": {"min": [0, 0, 0], "max": [1e-30, 1e-30, 1e-30]}, "resolution": 16})")) ==
        "smoke.json:/volume/bounds: the volume's voxels (6.25e-32) are smaller than the least "
        "eikon resolves here, 2e-05 (OpenVDB's transforms need a voxel volume above 3e-15): "
        "enlarge the box or use fewer voxels");
    CHECK(
        errorOf(
            sceneWith(
                R"("simulation": {"domain": {"min": [0, 0, 0], "max": [1e-30, 1e-30, 1e-30]}, "resolution": 8})"))
            .rfind("smoke.json:/simulation/domain: the domain's cells (1.25e-31) are smaller", 0) ==
        0);
    // Far from the origin, float precision sets the limit.
    CHECK(
        errorOf(
            sceneWith(
                R"("volume": {"bounds": {"min": [1e6, 0, 0], "max": [1000001, 1, 1]}, "resolution": 64})"))
            .find("(float positions 1e+06 from the origin step by 0.119209)") != std::string::npos);
    CHECK(
        errorOf(
            R"({"sources": [{"type": "sphere", "voxel_size": 1e-9}], "materials": [{"name": "m"}]})")
            .rfind("smoke.json:/sources/0/voxel_size: the voxels (1e-09) are smaller", 0) == 0);
    // An ordinary small volume still reads.
    CHECK_NOTHROW(eikon::parseScene(
        sceneWith(
            R"("volume": {"bounds": {"min": [0, 0, 0], "max": [0.01, 0.01, 0.01]}, "resolution": 64})"),
        "smoke.json"));
}

TEST_CASE("a key with control characters is escaped in the JSON pointer too", "[scene][json]") {
    // tests/fuzz/regressions/scene/key_with_tab.json (found by fuzz_scene): the reason quoted the
    // key escaped, but the pointer in where() carried the raw tab; a line end there split the
    // one-line message.
    CHECK(regressionError("key_with_tab.json").rfind(":/volume/\\t: unknown key '\\t'", 0) == 0);

    const std::string line = errorOf(sceneWith(R"("camera": {"look_\nat": [0, 0, 0]})"));
    INFO(line);
    CHECK_FALSE(eikon::hasControlCharacter(line));
    CHECK(line.rfind("smoke.json:/camera/look_\\nat: ", 0) == 0);

    // A long key is cut in the pointer as in the reason.
    const std::string longKey = errorOf(R"({"volume": {")" + std::string(300, 'k') + R"(": 1}})");
    CHECK(longKey.rfind("smoke.json:/volume/" + std::string(80, 'k') + "...: ", 0) == 0);
}

TEST_CASE("a value quoted in a message has DEL escaped too", "[scene][json]") {
    // JSON's escapes cover the control characters below 0x20; DEL (0x7f) was quoted raw
    // (tests/fuzz/regressions/scene/string_with_del.json, found by fuzz_scene).
    CHECK(regressionError("string_with_del.json").find("got \"\\x7f\"") != std::string::npos);
    CHECK(
        errorOf(sceneWith(R"("output": {"directory": "\u007fout"})")) ==
        R"(smoke.json:/output/directory: expected a string without control characters, got "\x7fout")");
}
