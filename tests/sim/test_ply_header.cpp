// PLY files that crashed or hung OpenMesh's reader (issue 14), each now one eikon::Error naming
// the file and line: the header grammar (sim/ply_header.h), what OpenMesh can read
// (sim/mesh_file_checks.h), and counts against the bytes that back them (sim/ply_body.h). Each
// case ran under `timeout 10` and an address-space limit before the fix: SEGV, or an endless loop
// allocating gigabytes.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

#include "core/error.h"
#include "sim/mesh_io.h"
#include "sim/mesh_test_files.h"
#include "sim/ply_header.h"
#include "support/test_paths.h"

using eikon::Error;
using eikon::loadMesh;
using namespace eikon::test;

namespace {

const std::string kTriangleBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

// An ASCII triangle whose header lines are `lines` (between `ply` and `end_header`).
std::string asciiTriangle(const std::string& lines) {
    return "ply\n" + lines + "end_header\n" + kTriangleBody;
}

const std::string kGoodLines =
    "format ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\n";

// Loads `text` written to a file in a fresh folder; returns "<where>: <reason>" of the error
// with the folder cut off, or fails when there is none.
std::string plyError(const std::string& name, const std::string& text) {
    const std::string dir = scratchDir("ply_header_" + name);
    const std::string path = dir + "/" + name + ".ply";
    writeText(path, text);
    try {
        loadMesh(path);
    } catch (const Error& e) {
        INFO(e.what());
        CHECK(e.where().rfind(path, 0) == 0);
        return std::string(e.what()).substr(dir.size() + 1);
    }
    FAIL("loading " << name << " did not throw");
    return {};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("a well-formed PLY header still reads, with comments, CRLF and synonyms", "[ply]") {
    const std::string dir = scratchDir("ply_header_good");
    writeText(dir + "/t.ply",
              asciiTriangle("format ascii 1.0\ncomment made by hand\n" + kGoodLines.substr(17)));
    CHECK(loadMesh(dir + "/t.ply").faces == 1);
    std::string crlf = asciiTriangle(replaced(kGoodLines, "float z", "float32 z"));
    for (std::size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2))
        crlf.replace(at, 1, "\r\n");
    writeText(dir + "/crlf.ply", crlf);
    CHECK(loadMesh(dir + "/crlf.ply").faces == 1);
    // Trailing blanks on the first line, as some writers leave them.
    writeText(dir + "/blank.ply", "ply \n" + asciiTriangle(kGoodLines).substr(4));
    CHECK(loadMesh(dir + "/blank.ply").faces == 1);
    writeText(dir + "/cube.ply", plyBinaryBytes(unitCubeQuads()));
    CHECK(loadMesh(dir + "/cube.ply").faces == 6);
}

TEST_CASE("a PLY property before any element is an error, not a SEGV in OpenMesh", "[ply]") {
    // The 68-byte input the fuzzer found, minimized: OpenMesh's can_u_read took
    // elements_.back() of an empty list.
    const std::string text =
        "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n";
    CHECK(plyError("property_first", text) ==
          "property_first.ply:3: a 'property' line before any 'element' line (each property "
          "belongs to the element above it)");
}

TEST_CASE("PLY headers that made OpenMesh loop forever are errors naming the line", "[ply]") {
    const std::string format =
        ": expected 'format ascii|binary_little_endian|binary_big_endian 1.0', got ";
    CHECK(plyError("no_version", asciiTriangle(replaced(kGoodLines, "ascii 1.0", "ascii"))) ==
          "no_version.ply:2" + format + "'format ascii'");
    for (const char* version : {"-inf", "abc", "1e308", "2.0"}) {
        INFO(version);
        CHECK(plyError("version", asciiTriangle(replaced(kGoodLines, "ascii 1.0",
                                                         std::string("ascii ") + version))) ==
              "version.ply:2" + format + "'format ascii " + version + "' (version '" + version +
                  "')");
    }
    CHECK(plyError("list_type", asciiTriangle(replaced(kGoodLines, "uchar int", "uchar i#t"))) ==
          "list_type.ply:8: unknown property type 'i#t' (expected char, uchar, short, ushort, "
          "int, uint, float, double, int8, uint8, int16, uint16, int32, uint32, float32 or "
          "float64)");
    CHECK(plyError("list_word", asciiTriangle(replaced(kGoodLines, "list uchar", "lis uchar"))) ==
          "list_word.ply:8: expected 'property TYPE NAME', got 'property lis uchar int "
          "vertex_indices'");
    CHECK(plyError("count_type", asciiTriangle(replaced(kGoodLines, "list uchar", "list float"))) ==
          "count_type.ply:8: list count type 'float' is not an integer type (char, uchar, short, "
          "ushort, int, uint, int8, uint8, int16, uint16, int32 or uint32)");
    // `end_header` glued to another word: our old check found the text, OpenMesh never did.
    CHECK(plyError("glued_end", "ply\n" + kGoodLines + "xend_header\n" + kTriangleBody) ==
          "glued_end.ply: the PLY header never ends (no 'end_header' line): truncated or corrupt");
    CHECK(plyError("keyword", asciiTriangle(kGoodLines + "elemnt edge 0\n")) ==
          "keyword.ply:9: expected 'element', 'property', 'comment', 'obj_info' or 'end_header' "
          "at the start of a header line, got 'elemnt edge 0'");
    CHECK(plyError("count", asciiTriangle(replaced(kGoodLines, "vertex 3", "vertex -3"))) ==
          "count.ply:3: element 'vertex' count '-3' is not a whole number below 2^32");
    CHECK(plyError("twice", asciiTriangle(replaced(kGoodLines, "float z\n",
                                                   "float z\nproperty float x\n"))) ==
          "twice.ply:7: property 'x' of element 'vertex' is declared twice");
    // Control characters in the header are escaped in the message, never printed raw.
    CHECK(plyError("control", asciiTriangle(replaced(kGoodLines, "float x", "fl\x1b[2Jt x"))) ==
          "control.ply:4: unknown property type 'fl\\x1b[2Jt' (expected char, uchar, short, "
          "ushort, int, uint, float, double, int8, uint8, int16, uint16, int32, uint32, float32 "
          "or float64)");
}

TEST_CASE("PLY properties OpenMesh would misread are errors, not endless output", "[ply]") {
    // `property list int float vertex_indices` in a binary file: OpenMesh printed "unsupported
    // conversion type to integral: 14" without end.
    std::string binary = plyBinaryBytes(unitCubeTriangles());
    CHECK(plyError("float_indices", replaced(binary, "list uchar int", "list int float")) ==
          "float_indices.ply:8: property 'vertex_indices' of element 'face' has items of type "
          "'float'; vertex indices are integers");
    CHECK(plyError("uint_count", replaced(binary, "list uchar int", "list uint int")) ==
          "uint_count.ply:8: property 'vertex_indices' of element 'face' has count type 'uint'; "
          "OpenMesh's PLY reader takes uchar, uint8, uint16 or int");
    CHECK(plyError("int_x", replaced(binary, "float x", "int x")) ==
          "int_x.ply:4: property 'x' of element 'vertex' has type 'int'; OpenMesh reads it from "
          "a binary file only as float or double");
    CHECK(plyError("list_texcoord",
                   asciiTriangle(kGoodLines + "property list uchar float texcoord\n")) ==
          "list_texcoord.ply:9: property 'texcoord' of element 'face' is a list, which OpenMesh's "
          "PLY reader cannot skip (only the face element's vertex_indices may be one)");
    CHECK(plyError("no_z", asciiTriangle(replaced(kGoodLines, "property float z\n", ""))) ==
          "no_z.ply:3: element 'vertex' has no 'z' property");
}

TEST_CASE("PLY counts larger than the file are errors before anything is allocated", "[ply]") {
    // A face count of 99,999,999 in a small file left the edge sort at 3.5 GB.
    CHECK(plyError("many_faces", asciiTriangle(replaced(kGoodLines, "face 1", "face 99999999"))) ==
          "many_faces.ply: element 'face' declares 99999999 items, which need at least 199999998 "
          "bytes (two per value), but the file has 9 bytes left for it: truncated or corrupt");
    std::string binary = plyBinaryBytes(unitCubeTriangles());
    CHECK(plyError("many_vertices", replaced(binary, "vertex 8", "vertex 4000000000")) ==
          "many_vertices.ply: element 'vertex' declares 4000000000 items, which need at least "
          "48000000000 bytes, but the file has 252 bytes left for it: truncated or corrupt");
    // A list count past the end of the file (the first face's uchar count set to 255).
    const std::size_t firstFace = binary.find("end_header\n") + 11 + 8 * 12;
    std::string longList = binary;
    longList[firstFace] = char(255);
    CHECK(plyError("long_list", longList) ==
          "long_list.ply: 'face' item 1 list 'vertex_indices' holds 255 values, past the end of "
          "the file (at byte " +
              std::to_string(firstFace + 1) + "): truncated or corrupt");
    // The count as an int, set to -1 (the data after it no longer matters).
    std::string negative = replaced(binary, "list uchar int", "list int int");
    const std::size_t negativeFace = negative.find("end_header\n") + 11 + 8 * 12;
    negative = negative.substr(0, negativeFace) + std::string("\xff\xff\xff\xff", 4) +
               negative.substr(negativeFace + 1);
    CHECK(plyError("negative", negative).find("'face' item 1 list 'vertex_indices' has count -1") !=
          std::string::npos);
    CHECK(plyError("cut", binary.substr(0, binary.size() - 13)) ==
          "cut.ply: the file ends inside 'face' item 12 (property 'vertex_indices'): truncated");
    // ASCII values OpenMesh's `>>` would fail on, leaving the rest unread.
    CHECK(plyError("nan", asciiTriangle(kGoodLines)
                              .replace(asciiTriangle(kGoodLines).find("1 0 0\n"), 1, "nan")) ==
          "nan.ply:11: 'vertex' item 2 property 'x': expected a finite number a float can hold, "
          "got 'nan'");
    CHECK(plyError("huge_list", replaced(asciiTriangle(kGoodLines), "3 0 1 2", "4000000000 0")) ==
          "huge_list.ply:13: 'face' item 1 list 'vertex_indices' has count 4000000000, more "
          "values than the rest of the file holds: truncated or corrupt");
}

TEST_CASE("the canonical PLY header is what the grammar read", "[ply]") {
    const std::string text =
        "ply\r\nformat  binary_big_endian 1\r\ncomment x\r\nelement v 2\r\n"
        "property   uint8 a\r\nproperty list int16 uint b\r\nend_header\r\n";
    const eikon::PlyHeader header = eikon::parsePlyHeader("t.ply", text);
    CHECK(header.bodyOffset == text.size());
    CHECK(eikon::canonicalPlyHeader(header) ==
          "ply\nformat binary_big_endian 1.0\nelement v 2\nproperty uint8 a\n"
          "property list int16 uint b\nend_header\n");
}
