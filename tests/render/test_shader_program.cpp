// Host-side #include expansion, #line mapping of driver logs, and compile errors that name the
// real file and line. Fixtures live in shaders/test/.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.h"
#include "render/gl_context.h"
#include "render/shader_program.h"
#include "support/test_paths.h"

namespace {

const std::string kFixtures = eikon::test::sourcePath("shaders/test/");

size_t occurrences(const std::string& text, const std::string& fragment) {
    size_t n = 0;
    for (size_t at = text.find(fragment); at != std::string::npos; at = text.find(fragment, at + 1))
        ++n;
    return n;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    size_t begin = 0;
    for (size_t end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1)
        out.push_back(text.substr(begin, end - begin));
    return out;
}

// Points EIKON_SHADER_DIR elsewhere for one test and restores it.
class ScopedShaderDir {
public:
    explicit ScopedShaderDir(const std::string& dir) {
        if (const char* old = std::getenv("EIKON_SHADER_DIR")) old_ = old;
        setenv("EIKON_SHADER_DIR", dir.c_str(), 1);
    }
    ~ScopedShaderDir() {
        if (old_.empty()) {
            unsetenv("EIKON_SHADER_DIR");
        } else {
            setenv("EIKON_SHADER_DIR", old_.c_str(), 1);
        }
    }

private:
    std::string old_;
};

}  // namespace

TEST_CASE("includes expand nested, once each, relative to the includer then the root", "[shader]") {
    const eikon::ShaderSource source = eikon::expandShaderSource("test/include_top.glsl");
    const std::string& text = source.text;
    CHECK(lines(text).front() == "#version 430 core");

    // include_common.glsl is reached as "include_common.glsl", "../include_common.glsl" and
    // "test/include_common.glsl" (from the root); it must appear once.
    CHECK(occurrences(text, "const float COMMON_MARKER") == 1);
    CHECK(occurrences(text, "const float A_MARKER") == 1);
    CHECK(occurrences(text, "const float SIBLING_MARKER") == 1);
    CHECK(occurrences(text, "const float B_MARKER") == 1);
    CHECK(text.find("COMMON_MARKER") < text.find("A_MARKER"));
    CHECK(text.find("A_MARKER") < text.find("SIBLING_MARKER"));
    CHECK(text.find("SIBLING_MARKER") < text.find("B_MARKER"));
    CHECK(text.find("B_MARKER") < text.find("TOP_MARKER"));
    CHECK(text.find("#include") == std::string::npos);

    const std::vector<std::string> expectedFiles = {
        kFixtures + "include_top.glsl", kFixtures + "include_a.glsl",
        kFixtures + "include_common.glsl", kFixtures + "sub/include_b.glsl",
        kFixtures + "sub/include_sibling.glsl"};
    CHECK(source.files == expectedFiles);
    // Each file starts at its line 1, numbered k * kShaderLinesPerFile + 1 under source string
    // k, and the includer resumes on the line after its #include.
    CHECK(text.find("#line 100001 1\n") != std::string::npos);
    CHECK(text.find("#line 100003 1\n") != std::string::npos);
    CHECK(text.find("#line 4 0\n") != std::string::npos);
    CHECK(text.find("#line 400001 4\n") != std::string::npos);
    CHECK(text.find("#line 300004 3\n") != std::string::npos);
    CHECK(text.find("#line 5 0\n") != std::string::npos);
}

TEST_CASE("defines follow #version and line numbers continue after them", "[shader]") {
    const std::string text =
        eikon::expandShaderSource("test/include_top.glsl", {"FAST", "STEPS=8", "MODE 2"}).text;
    const std::vector<std::string> l = lines(text);
    REQUIRE(l.size() > 5);
    CHECK(l[0] == "#version 430 core");
    CHECK(l[1] == "#define FAST");
    CHECK(l[2] == "#define STEPS 8");
    CHECK(l[3] == "#define MODE 2");
    CHECK(l[4] == "#line 3 0");  // #version is line 2 of include_top.glsl
}

TEST_CASE("an include cycle expands each file once and ends", "[shader]") {
    const std::string text = eikon::loadShaderSource("test/include_cycle_a.glsl");
    CHECK(occurrences(text, "const float CYCLE_A") == 1);
    CHECK(occurrences(text, "const float CYCLE_B") == 1);
}

TEST_CASE("a missing include names the including file and line", "[shader]") {
    try {
        eikon::loadShaderSource("test/include_missing.glsl");
        FAIL("no error for a missing include");
    } catch (const eikon::Error& e) {
        CHECK(e.where() == kFixtures + "include_missing.glsl:3");
        CHECK_THAT(e.reason(), Catch::Contains("\"does_not_exist.glsl\""));
    }
}

TEST_CASE("a missing shader file is an Error naming it", "[shader]") {
    CHECK_THROWS_WITH(eikon::loadShaderSource("test/no_such_shader.comp"),
                      Catch::Contains("no_such_shader.comp: cannot read shader file"));
}

TEST_CASE("EIKON_SHADER_DIR moves the shaders root at run time", "[shader]") {
    ScopedShaderDir dir(kFixtures);
    CHECK(eikon::shaderDirectory() == kFixtures);
    const std::string text = eikon::loadShaderSource("include_a.glsl");
    CHECK(occurrences(text, "COMMON_MARKER = 10.0") == 1);
}

TEST_CASE("driver logs are rewritten to file:line", "[shader]") {
    const std::vector<std::string> files = {"/s/top.comp", "/s/inc.glsl"};
    // Mesa
    CHECK(eikon::rewriteShaderLog("1:12(5): error: `x' undeclared\n", files) ==
          "/s/inc.glsl:12: error: `x' undeclared\n");
    // NVIDIA
    CHECK(eikon::rewriteShaderLog("0(7) : error C1008: undefined variable \"x\"\n", files) ==
          "/s/top.comp:7: error C1008: undefined variable \"x\"\n");
    // AMD
    CHECK(eikon::rewriteShaderLog("ERROR: 1:3: 'x' : undeclared identifier\n", files) ==
          "/s/inc.glsl:3: error: 'x' : undeclared identifier\n");
    // Mesa reports source 0 for most errors; the line number still names the include.
    CHECK(eikon::rewriteShaderLog("0:100006(20): error: `x' undeclared\n", files) ==
          "/s/inc.glsl:6: error: `x' undeclared\n");
    // Unknown source-string numbers and other lines stay as they are.
    CHECK(eikon::rewriteShaderLog("5:1(1): error: y\n0:200001(1): error: w\nlink: z\n", files) ==
          "5:1(1): error: y\n0:200001(1): error: w\nlink: z\n");
}

TEST_CASE("a compile error reports the included file and its line", "[shader][gl]") {
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    try {
        eikon::ShaderProgram::compute("test/compile_error.comp");
        FAIL("the deliberate mistake compiled");
    } catch (const eikon::Error& e) {
        INFO(e.what());
        CHECK(e.where() == kFixtures + "compile_error.comp");
        CHECK_THAT(e.reason(),
                   Catch::StartsWith(kFixtures + "compile_error_include.glsl:6: error"));
    }
}

TEST_CASE("defines reach the compiler", "[shader][gl]") {
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    // Defining gid_double.comp's uniform name `count` as a literal breaks the declaration, which
    // only happens if the define is compiled in.
    CHECK_NOTHROW(eikon::ShaderProgram::compute("test/gid_double.comp", {"UNUSED_FLAG"}));
    CHECK_THROWS_AS(eikon::ShaderProgram::compute("test/gid_double.comp", {"count=3"}),
                    eikon::Error);
}

TEST_CASE("a moved-from program owns nothing", "[shader][gl]") {
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    eikon::ShaderProgram a = eikon::ShaderProgram::compute("test/gid_double.comp");
    const unsigned id = a.id();
    REQUIRE(id != 0);
    eikon::ShaderProgram b = std::move(a);
    CHECK(a.id() == 0);
    CHECK(b.id() == id);
    CHECK(b.localSize() == std::array<int, 3>{64, 1, 1});
    CHECK(b.uniformLocation("count") >= 0);
    CHECK(b.uniformLocation("notAUniform") == -1);
}
