// OFF files as OpenMesh reads them (sim/off_header.h): the first line decides binary or ASCII,
// and the counts come from after it. Binary files are walked record by record
// (sim/off_binary.h), ASCII counts are checked against the bytes (sim/mesh_file_checks.h). Before,
// counts the file could not back made OpenMesh allocate and loop by them: out of memory, or past
// `timeout 20` at 2 GB. ASCII bodies are walked value by value (sim/off_ascii.h).
// tests/fuzz/regressions/off/ holds the files fuzz_off found.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <string>

#include "core/error.h"
#include "sim/mesh_io.h"
#include "sim/mesh_test_files.h"
#include "sim/off_header.h"
#include "support/test_paths.h"

using eikon::Error;
using eikon::loadMesh;
using eikon::readOffHeader;
using namespace eikon::test;

namespace {

// `bytes` with the 32-bit little-endian value at `at` replaced by `value`.
std::string patched(std::string bytes, std::size_t at, std::uint32_t value) {
    std::memcpy(&bytes[at], &value, 4);  // little-endian host, as the format
    return bytes;
}

// Where the counts start: just after the first line.
std::size_t countsAt(const std::string& bytes) {
    return bytes.find('\n') + 1;
}

std::string loadError(const std::string& dir, const std::string& name, const std::string& bytes) {
    const std::string path = dir + "/" + name;
    writeText(path, bytes);
    try {
        loadMesh(path);
    } catch (const Error& e) {
        CHECK(e.where() == path);
        return e.reason();
    }
    FAIL(name << " loaded");
    return {};
}

}  // namespace

TEST_CASE("the first line of an OFF file is read as OpenMesh reads it", "[off_files]") {
    const auto binary = [](const std::string& bytes) { return readOffHeader(bytes).binary; };
    CHECK(binary("OFF BINARY\n"));
    CHECK(binary("OFF BINARY"));
    CHECK(binary("STCNOFF BINARY\n"));
    CHECK(binary("OFFxBINARY\n"));  // OpenMesh skips any one character after OFF
    CHECK_FALSE(binary("OFF  BINARY\n"));
    CHECK_FALSE(binary("OFF\nBINARY\n"));
    CHECK_FALSE(binary("OFF\n3 1 0\n"));
    CHECK_FALSE(binary("NCOFF BINARY\n"));  // the prefix letters come in one order
    CHECK_FALSE(binary("OF"));

    CHECK(readOffHeader("OFF\x01 anything").readable);  // "OFF" starts the line; the rest is free
    CHECK(readOffHeader("COFF\n").readable);
    CHECK_FALSE(readOffHeader("4OFF\n").readable);  // OpenMesh refuses other dimensions
    CHECK_FALSE(readOffHeader("nOFF\n").readable);
    CHECK_FALSE(readOffHeader(" OFF\n").readable);
    CHECK(readOffHeader("OFF 3 1 0\n0 0 0").bodyOffset == 10);
    CHECK_FALSE(readOffHeader("OFF").lineEnded);
}

TEST_CASE("binary OFF files with and without prefixes load", "[off_files]") {
    const std::string dir = scratchDir("off_files_binary_good");
    const PolygonMesh cube = unitCubeQuads();
    const struct {
        const char* line;
        std::size_t extra;  // bytes per vertex after x, y, z
    } variants[] = {{"OFF BINARY", 0},   {"OFFxBINARY", 0},   {"COFF BINARY", 12},
                    {"NOFF BINARY", 12}, {"STOFF BINARY", 8}, {"STCNOFF BINARY", 32}};
    for (const auto& v : variants) {
        INFO(v.line);
        const std::string path = dir + "/cube.off";
        writeText(path, offBinaryBytes(cube, v.line, v.extra) + "trailing bytes are ignored");
        const eikon::LoadedMesh loaded = loadMesh(path);
        CHECK(loaded.faces == 6);
        CHECK(loaded.mesh.positions.size() == 8);
        CHECK(loaded.mesh.triangles.size() == 12);
        CHECK(loaded.mesh.positions[7].x == 1.0f);
    }
}

TEST_CASE("binary OFF counts the file cannot back are one error, not a huge allocation",
          "[off_files]") {
    const std::string dir = scratchDir("off_files_binary_counts");
    const std::string cube = offBinaryBytes(unitCubeQuads());
    const std::size_t counts = countsAt(cube);
    const std::size_t firstFace = counts + 12 + 8 * 12;

    CHECK(loadError(dir, "faces.off", patched(cube, counts + 4, 0xffffffffu)) ==
          "binary OFF declares 8 vertices and 4294967295 faces, which need at least 17179869276 "
          "bytes, but 216 follow the counts: truncated or corrupt");
    CHECK(loadError(dir, "vertices.off", patched(cube, counts, 0x80000000u)) ==
          "binary OFF declares 2147483648 vertices and 6 faces, which need at least 25769803800 "
          "bytes, but 216 follow the counts: truncated or corrupt");
    CHECK(loadError(dir, "corners.off", patched(cube, firstFace, 0xfffffff0u)) ==
          "binary OFF: face 1 declares 4294967280 vertices, but 116 bytes are left: truncated or "
          "corrupt");
    CHECK(loadError(dir, "cut.off", cube.substr(0, cube.size() - 10)) ==
          "binary OFF: face 6 declares 4 vertices, but 6 bytes are left: truncated or corrupt");
    CHECK(loadError(dir, "cut_before_face.off", cube.substr(0, firstFace + 5 * 20 + 2)) ==
          "binary OFF: the file ends before face 6 of 6: truncated");
    CHECK(loadError(dir, "no_counts.off", std::string("OFF BINARY\n\1\0\0", 14)) ==
          "binary OFF: the file ends before the vertex, face and edge counts (3 of 12 bytes)");
    CHECK(loadError(dir, "no_line_end.off", "OFF BINARY") ==
          "binary OFF: the header line has no end, so there are no counts");
}

TEST_CASE("ASCII OFF counts are read after the first line, where OpenMesh reads them",
          "[off_files]") {
    const std::string dir = scratchDir("off_files_ascii_counts");
    // Counts on the first line are not what OpenMesh reads: it took 4e9 from the second line and
    // ran out of memory.
    CHECK(loadError(dir, "second_line.off",
                    "OFF 3 1 0\n4000000000 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
          "the OFF header declares 4000000000 vertices and 4000000000 faces, which need at least "
          "32000000000 bytes, but 27 follow the counts: truncated or corrupt");
    // With no line end, OpenMesh read its counts from uninitialised memory (found by fuzz_off:
    // 2 GB and past `timeout 20`).
    CHECK(loadError(dir, "no_line_end.off", "OFF 3 1 0 0 0 0 1 0 0 0 1 0 3 0 1 2") ==
          "expected the vertex, face and edge counts after 'OFF 3 1 0 0 0 0 1 0 0 0 1 0 3 0 1 2', "
          "got ''");
    // Comments are not skipped before the counts: OpenMesh's `>>` stops at them.
    CHECK(loadError(dir, "comment.off",
                    "OFF\n# made by hand\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
          "expected the vertex, face and edge counts after 'OFF', got '# made by'");
    // A file the prefix check accepts with anything after "OFF" on its line.
    const eikon::LoadedMesh loaded = [&] {
        writeText(dir + "/glued.off", "OFF\x01\x7f\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        return loadMesh(dir + "/glued.off");
    }();
    CHECK(loaded.faces == 1);

    for (const char* name :
         {"header_without_line_end.off", "counts_after_first_line.off", "binary_face_count.off"}) {
        INFO(name);
        const std::string path = sourcePath(std::string("tests/fuzz/regressions/off/") + name);
        CHECK_THROWS_AS(loadMesh(path), Error);
    }
}

TEST_CASE("ASCII OFF bodies are walked as OpenMesh reads them", "[off_files]") {
    const std::string dir = scratchDir("off_files_ascii_body");
    // The variants still load: normals (N), colours on vertex and face lines (C), extra values at
    // the end of a vertex line, faces on one line.
    for (const char* text :
         {"NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n",
          "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2 1 1 1\n",
          "OFF\n3 1 0\n0 0 0 0.5 0.5\n1 0 0\n0 1 0\n3 0 1 2\r\n",
          "OFF\r\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2 3 0 2 3\n"}) {
        INFO(text);
        writeText(dir + "/ok.off", text);
        CHECK(loadMesh(dir + "/ok.off").mesh.triangles.size() >= 1);
    }
    const struct {
        const char* name;
        std::string text;
        const char* error;
    } cases[] = {
        // A face count the file cannot back: 4e9 indices pushed one by one until memory ran out
        // (tests/fuzz/regressions/off/face_count_in_body.off, found by fuzz_off).
        {"face_count.off", "OFF\n0 1 0\n4000000000 0 1 2\n",
         "truncated: the file ends before index 4 of face 1 of 1"},
        {"cut.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1",
         "truncated: the file ends before index 3 of face 1 of 1"},
        {"few_vertices.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n" + std::string(9, ' '),
         "truncated: the file ends before value 1 of vertex 3"},
        // A value `>>` cannot read fails the stream, and every later face repeats the last count.
        {"word.off", "OFF\n3 1 0\n0 0 x\n1 0 0\n0 1 0\n3 0 1 2\n",
         "value 3 of vertex 1 is 'x', not a number a float holds"},
        {"hex.off", "OFF\n3 1 0\n0x1p3 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
         "value 1 of vertex 1 is '0x1p3', not a number a float holds"},
        {"huge.off", "OFF\n3 1 0\n1e39 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
         "value 1 of vertex 1 is '1e39', not a number a float holds"},
        {"negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n",
         "the vertex count of face 1 of 1 is '-3', not a whole number"},
        {"index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n",
         "index 3 of face 1 of 1 is '2.5', not an integer"},
        {"edges.off", "OFF\n3 1 x\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
         "expected the vertex, face and edge counts after 'OFF', got '3 1 x'"},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        CHECK(loadError(dir, c.name, c.text) == c.error);
    }
}
