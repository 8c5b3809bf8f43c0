// OBJ face lines checked before OpenMesh reads them (sim/obj_face_lines.h). "f /0", a corner with
// no vertex index, tripped an assertion in Debian's OpenMesh and aborted the program (found by
// fuzz_obj, tests/fuzz/regressions/obj/).
#include <catch2/catch.hpp>

#include <string>

#include "core/error.h"
#include "sim/mesh_io.h"
#include "sim/mesh_test_files.h"
#include "support/test_paths.h"

using eikon::Error;
using eikon::loadMesh;
using namespace eikon::test;

namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";

std::string faceError(const std::string& dir, const std::string& name, const std::string& text) {
    const std::string path = dir + "/" + name;
    writeText(path, text);
    try {
        loadMesh(path);
    } catch (const Error& e) {
        return std::string(e.what()).substr(dir.size() + 1);
    }
    FAIL(name << " loaded");
    return {};
}

}  // namespace

TEST_CASE("OBJ face corners in every form OBJ allows still load", "[obj_faces]") {
    const std::string dir = scratchDir("obj_faces_good");
    for (const char* face : {"f 1 2 3", "f 1/1 2/1 3/1", "f 1//1 2//1 3//1", "f 1/1/1 2/1/1 3/1/1",
                             "f -3 -2 -1", "  f\t1 2 3  \r", "f 1/1/ 2/1/ 3/1/"}) {
        INFO(face);
        writeText(dir + "/t.obj", kTriangle + face + "\n# done\n");
        CHECK(loadMesh(dir + "/t.obj").faces == 1);
    }
}

TEST_CASE("an OBJ face corner without a vertex index is an error, not an abort", "[obj_faces]") {
    const std::string dir = scratchDir("obj_faces_bad");
    CHECK(faceError(dir, "slash.obj", kTriangle + "f /0\n") ==
          "slash.obj:6: face corner 1 ('/0') is not v, v/vt, v//vn or v/vt/vn with whole-number "
          "indices");
    CHECK(faceError(dir, "normal.obj", kTriangle + "f 1//1 //1 3//1\n") ==
          "normal.obj:6: face corner 2 ('//1') is not v, v/vt, v//vn or v/vt/vn with whole-number "
          "indices");
    // What OpenMesh skipped without a word, dropping a corner, or read as the vertex before the
    // first.
    CHECK(faceError(dir, "word.obj", kTriangle + "f 1 2 3 x\n")
              .find("word.obj:6: face corner 4 ('x')") == 0);
    CHECK(faceError(dir, "letter.obj", kTriangle + "f a/1 2 3\n")
              .find("letter.obj:6: face corner 1") == 0);
    CHECK(faceError(dir, "four.obj", kTriangle + "f 1/1/1/1 2 3\n").find("four.obj:6: ") == 0);
    CHECK(faceError(dir, "huge.obj", kTriangle + "f 1 2 99999999999\n").find("huge.obj:6: ") == 0);
    CHECK(faceError(dir, "escape.obj", kTriangle + "f 1 2 \x1b[2J\n") ==
          "escape.obj:6: face corner 3 ('\\x1b[2J') is not v, v/vt, v//vn or v/vt/vn with "
          "whole-number indices");

    const std::string regression =
        sourcePath("tests/fuzz/regressions/obj/face_without_vertex_index.obj");
    CHECK_THROWS_AS(loadMesh(regression), Error);
}
