// Scanned volumes: NRRD headers (raw, gzip and ascii samples, attached and detached), headerless
// raw files named as the SciVis collection names them, the real CT scans of ../shared/data/volumes
// against what numpy reads from the same bytes, and the one-line errors for files that do not
// match what they say.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include <zlib.h>

#include "core/error.h"
#include "core/field_registry.h"
#include "core/scan_layout.h"
#include "core/scan_volume.h"
#include "core/scene.h"
#include "core/scene_sources.h"
#include "support/contains.h"
#include "support/test_paths.h"

using eikon::test::contains;

namespace {

// A 4×3×2 volume whose sample (i, j, k) is 100·k + 10·j + i, except sample (0, 0, 0), which is 0.
constexpr int kX = 4, kY = 3, kZ = 2;
std::vector<std::uint16_t> testSamples() {
    std::vector<std::uint16_t> v;
    for (int k = 0; k < kZ; ++k)
        for (int j = 0; j < kY; ++j)
            for (int i = 0; i < kX; ++i) v.push_back(std::uint16_t(100 * k + 10 * j + i));
    return v;
}

std::string bytesOf(const std::vector<std::uint16_t>& samples, bool bigEndian) {
    std::string out;
    for (std::uint16_t s : samples) {
        const char lo = char(s & 0xff), hi = char(s >> 8);
        out += bigEndian ? std::string{hi, lo} : std::string{lo, hi};
    }
    return out;
}

void writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

// Appends `bytes` to `path` as one gzip member, as teem writes an attached gzip NRRD.
void appendGzip(const std::string& path, const std::string& bytes) {
    gzFile gz = gzopen(path.c_str(), "ab");
    REQUIRE(gz != nullptr);
    REQUIRE(gzwrite(gz, bytes.data(), unsigned(bytes.size())) == int(bytes.size()));
    gzclose(gz);
}

std::string header(const std::string& type, const std::string& encoding,
                   const std::string& extra = "") {
    return "NRRD0004\n# written by a test\ntype: " + type + "\ndimension: 3\nsizes: 4 3 2\n" +
           "encoding: " + encoding + "\n" + extra;
}

void expectTestVolume(const eikon::ScanVolume& scan) {
    const auto acc = scan.grid->getConstAccessor();
    for (int k = 0; k < kZ; ++k)
        for (int j = 0; j < kY; ++j)
            for (int i = 0; i < kX; ++i)
                REQUIRE(acc.getValue(openvdb::Coord(i, j, k)) == float(100 * k + 10 * j + i));
    CHECK_FALSE(acc.isValueOn(openvdb::Coord(0, 0, 0)));  // an exact 0 stays background
    CHECK(scan.grid->activeVoxelCount() == kX * kY * kZ - 1);
    CHECK(scan.storedMin == 0.0);
    CHECK(scan.storedMax == 123.0);
}

std::string errorOf(const eikon::ScanLayout& layout, const eikon::ScanReadOptions& options = {}) {
    try {
        eikon::readScanVolume(layout, options);
    } catch (const eikon::Error& e) {
        return e.what();
    }
    return "(no error)";
}

std::string headerErrorOf(const std::string& path) {
    try {
        eikon::readNrrdHeader(path);
    } catch (const eikon::Error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("NRRD with attached raw big-endian samples, spacings and origin", "[scan]") {
    const std::string dir = eikon::test::scratchDir("scan_raw_nrrd");
    const std::string path = dir + "/v.nrrd";
    writeFile(path, header("unsigned short", "raw",
                           "endian: big\nspacings: 0.5 2 1.5\nspace origin: (1,-2,3)\n"
                           "content: a test\nkey:=value\n\n") +
                        bytesOf(testSamples(), true));
    REQUIRE(eikon::isNrrdFile(path));
    const eikon::ScanLayout layout = eikon::readNrrdHeader(path);
    CHECK(layout.dims == glm::ivec3(kX, kY, kZ));
    CHECK(layout.type == eikon::ScanValueType::UInt16);
    CHECK(layout.bigEndian);
    CHECK(layout.describe() == "4×3×2 uint16");
    const eikon::ScanVolume scan = eikon::readScanVolume(layout, {});
    expectTestVolume(scan);
    // Sample (i, j, k) sits at origin + (i, j, k)·spacing.
    const openvdb::Vec3d p = scan.grid->indexToWorld(openvdb::Coord(3, 2, 1));
    CHECK(p.x() == Approx(1.0 + 3 * 0.5));
    CHECK(p.y() == Approx(-2.0 + 2 * 2.0));
    CHECK(p.z() == Approx(3.0 + 1 * 1.5));
}

TEST_CASE("NRRD with gzip samples, byte skip and space directions", "[scan]") {
    const std::string dir = eikon::test::scratchDir("scan_gzip_nrrd");
    const std::string path = dir + "/v.nrrd";
    writeFile(path, header("uint16", "gzip",
                           "endian: little\nbyte skip: 3\n"
                           "space directions: (0.5,0,0) (0,0.5,0) (0,0,2.5)\n\n"));
    appendGzip(path, "xyz" + bytesOf(testSamples(), false));
    const eikon::ScanLayout layout = eikon::readNrrdHeader(path);
    CHECK(layout.encoding == eikon::ScanEncoding::Gzip);
    CHECK(layout.spacing == glm::dvec3(0.5, 0.5, 2.5));
    expectTestVolume(eikon::readScanVolume(layout, {}));

    SECTION("a corrupt gzip stream") {
        std::string bytes;
        {
            std::ifstream in(path, std::ios::binary);
            bytes.assign(std::istreambuf_iterator<char>(in), {});
        }
        bytes[bytes.size() - 6] ^= 0x5a;  // the CRC-32 of the samples, which zlib checks
        writeFile(path, bytes);
        const std::string e = errorOf(eikon::readNrrdHeader(path));
        CHECK(contains(e, path + ": corrupt gzip stream (zlib: "));
    }
    SECTION("a gzip stream that ends early") {
        writeFile(path, header("uint16", "gzip", "endian: little\n\n"));
        appendGzip(path, bytesOf(testSamples(), false).substr(0, 30));
        const std::string e = errorOf(eikon::readNrrdHeader(path));
        CHECK(contains(e, "holds 30 bytes of samples once unzipped, and 4×3×2 uint16 is 48 bytes"));
    }
}

TEST_CASE("Detached NRRD header with ascii samples", "[scan]") {
    const std::string dir = eikon::test::scratchDir("scan_ascii_nhdr");
    std::string text = "first line skipped\n";
    for (std::uint16_t s : testSamples()) text += std::to_string(s) + (s % 3 ? " " : ",\n");
    writeFile(dir + "/v.txt", text);
    writeFile(dir + "/v.nhdr", header("float", "ascii", "line skip: 1\ndata file: v.txt\n"));
    expectTestVolume(eikon::readScanVolume(eikon::readNrrdHeader(dir + "/v.nhdr"), {}));

    writeFile(dir + "/v.txt", text + " 7");
    CHECK(contains(errorOf(eikon::readNrrdHeader(dir + "/v.nhdr")),
                   "holds more than the 24 samples of 4×3×2 float32"));
    writeFile(dir + "/v.txt", "skip\n1 2 three");
    CHECK(contains(errorOf(eikon::readNrrdHeader(dir + "/v.nhdr")),
                   "sample 2 (\"three\") is not a number"));
    writeFile(dir + "/v.txt", "skip\n1 2 3");
    CHECK(contains(errorOf(eikon::readNrrdHeader(dir + "/v.nhdr")),
                   "holds 3 samples, and 4×3×2 float32 is 24"));
    writeFile(dir + "/v.txt", "skip\n1 nan 3");
    CHECK(contains(errorOf(eikon::readNrrdHeader(dir + "/v.nhdr")),
                   "the sample at (1, 0, 0) is nan (NaN or infinite)"));
}

TEST_CASE("NRRD headers that are wrong get one line naming the field", "[scan]") {
    const std::string dir = eikon::test::scratchDir("scan_bad_headers");
    const std::string path = dir + "/v.nrrd";
    const std::string data = bytesOf(testSamples(), false);
    auto check = [&](const std::string& text, const std::string& expected) {
        writeFile(path, text);
        const std::string e = headerErrorOf(path);
        INFO(e);
        CHECK(contains(e, path + ": " + expected));
        CHECK(e.find('\n') == std::string::npos);
    };
    check(header("block", "raw", "endian: little\n\n") + data,
          "NRRD field \"type\": expected a scalar type");
    check(header("short", "bzip2", "endian: little\n\n") + data,
          "NRRD field \"encoding\": expected raw, gzip or ascii");
    check(header("short", "raw", "\n") + data,
          "the NRRD header has no \"endian\" field, which int16 samples need");
    check("NRRD0004\ntype: short\ndimension: 4\nsizes: 1 4 3 2\nencoding: raw\n\n" + data,
          "NRRD field \"dimension\": expected 3");
    check("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3\nencoding: raw\n\n" + data,
          "NRRD field \"sizes\": expected three sizes");
    check("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 99999\nencoding: raw\n\n" + data,
          "NRRD field \"sizes\": expected three integers in [1, 4096]");
    check("NRRD0004\ntype: uchar\ndimension: 3\nencoding: raw\n\n" + data,
          "the NRRD header has no \"sizes\" field");
    check(header("uchar", "raw", "data file: missing.raw\n"), "its data file");
    check(header("uchar", "raw", "data file: LIST\n"),
          "NRRD field \"data file\": expected one file");
    // The other spelling, named as the header spells it (fuzz_nrrd found its message read a
    // field that was not there).
    check(header("uchar", "raw", "datafile: v%03d.raw\n"),
          "NRRD field \"datafile\": expected one file");
    check(header("uchar", "raw", "spacings: 1 0 1\n\n") + data,
          "NRRD field \"spacings\": expected three numbers from 1e-6 to 1e6");
    // A spacing OpenVDB's transform cannot scale by (fuzz_nrrd: an ArithmeticError escaped).
    check(header("uchar", "raw", "space directions: (1,0,0) (0,1e-30,0) (0,0,1)\n\n") + data,
          "NRRD field \"space directions\": expected vectors 1e-6 to 1e6 long");
    check(header("uchar", "raw", "space directions: (1,0,0) (0,1,0)\n\n") + data,
          "NRRD field \"space directions\": expected three vectors");
    check(header("uchar", "raw"), "the header ends without a blank line");
    check(header("uchar", "raw", "this is not a field\n\n"),
          "NRRD header line \"this is not a field\" is neither");
    check("P6\n4 3\n255\n" + data, "not an NRRD file");
    check("NRRD0004\n" + std::string(70000, 'x') + "\n", "a header line longer than 64 KiB");
}

TEST_CASE("NRRD samples that do not match the header", "[scan]") {
    const std::string dir = eikon::test::scratchDir("scan_bad_samples");
    const std::string path = dir + "/v.nrrd";
    const std::string data = bytesOf(testSamples(), false);
    writeFile(path, header("ushort", "raw", "endian: little\n\n") + data.substr(0, 40));
    const std::string truncated = errorOf(eikon::readNrrdHeader(path));
    CHECK(contains(truncated, "holds 40 bytes of samples after its first"));
    CHECK(contains(truncated, "and 4×3×2 uint16 is 48 bytes: the file is truncated"));
    writeFile(path, header("ushort", "raw", "endian: little\n\n") + data + "!!");
    CHECK(contains(errorOf(eikon::readNrrdHeader(path)), "holds 50 bytes of samples"));
    // byte skip −1: the samples end the file, whatever comes before them.
    writeFile(path, header("ushort", "raw", "endian: little\nbyte skip: -1\n\n") + "junk" + data);
    expectTestVolume(eikon::readScanVolume(eikon::readNrrdHeader(path), {}));
}

TEST_CASE("Headerless raw files: layout from the name, or given", "[scan]") {
    const std::string dir = eikon::test::scratchDir("scan_raw_names");
    const std::string data = bytesOf(testSamples(), false);
    const std::string named = dir + "/part_4x3x2_uint16.raw";
    writeFile(named, data);
    const eikon::ScanLayout layout = eikon::rawScanLayout(named, std::nullopt, std::nullopt, false);
    CHECK(layout.dims == glm::ivec3(4, 3, 2));
    CHECK(layout.type == eikon::ScanValueType::UInt16);
    expectTestVolume(eikon::readScanVolume(layout, {}));

    const std::string plain = dir + "/volume.raw";
    writeFile(plain, bytesOf(testSamples(), true));
    expectTestVolume(eikon::readScanVolume(
        eikon::rawScanLayout(plain, glm::ivec3(4, 3, 2), eikon::ScanValueType::UInt16, true), {}));
    CHECK_THROWS_WITH(eikon::rawScanLayout(plain, std::nullopt, std::nullopt, false),
                      Catch::Contains(plain + ": a raw file needs its dimensions"));
    const std::string oddType = dir + "/part_4x3x2_uint12.raw";
    writeFile(oddType, data);
    CHECK_THROWS_WITH(eikon::rawScanLayout(oddType, std::nullopt, std::nullopt, false),
                      Catch::Contains("unknown value type \"uint12\" in the file name"));
    // Dimensions that do not match the file's size: the byte counts, not a misread volume.
    CHECK(contains(errorOf(eikon::rawScanLayout(named, glm::ivec3(4, 3, 3), std::nullopt, false)),
                   named + ": holds 48 bytes of samples, and 4×3×3 uint16 is 72 bytes"));
}

TEST_CASE("A window maps stored values to [0, 1], negative density is refused", "[scan]") {
    const std::string dir = eikon::test::scratchDir("scan_window");
    const std::string path = dir + "/hu_4x3x2_int16.raw";
    std::vector<std::uint16_t> samples = testSamples();
    samples[5] = std::uint16_t(std::int16_t(-1000));  // air, in Hounsfield units
    writeFile(path, bytesOf(samples, false));
    const eikon::ScanLayout layout = eikon::rawScanLayout(path, std::nullopt, std::nullopt, false);
    const std::string e = errorOf(layout);
    CHECK(contains(e, path + ": the sample at (1, 1, 0) is -1000, and field 'density' must not be "
                             "negative: map the scan's values to [0, 1] with \"window\""));
    eikon::ScanReadOptions labelled;
    labelled.fieldName = "density.ct";
    CHECK(contains(errorOf(layout, labelled), "field 'density.ct' must not be negative"));
    eikon::ScanReadOptions temperature;  // a temperature excess may be negative
    temperature.fieldName = "temperature";
    CHECK(eikon::readScanVolume(layout, temperature).storedMin == -1000.0);

    eikon::ScanReadOptions windowed;
    windowed.window = eikon::ScanWindow{-20.0, 80.0};
    const eikon::ScanVolume scan = eikon::readScanVolume(layout, windowed);
    const auto acc = scan.grid->getConstAccessor();
    CHECK_FALSE(acc.isValueOn(openvdb::Coord(1, 1, 0)));  // clamped to 0
    CHECK(acc.getValue(openvdb::Coord(0, 0, 0)) == Approx(0.2f));
    CHECK(acc.getValue(openvdb::Coord(3, 2, 0)) == Approx(43.0f / 100.0f));
    CHECK(acc.getValue(openvdb::Coord(3, 2, 1)) == 1.0f);  // 123 clamped
    CHECK(scan.storedMin == -1000.0);
}

TEST_CASE("The shared CT scans read as numpy reads their bytes", "[scan]") {
    struct Expected {
        const char* file;
        double sum;
        long long nonZero;
        openvdb::Coord at;
        float value;
    };
    // numpy.fromfile(file, dtype).reshape(z, y, x): sum, count_nonzero and one sample each.
    const Expected scans[] = {
        {"tooth_103x94x161_uint8.raw", 160814065.0, 1558787, openvdb::Coord(60, 50, 80), 56.0f},
        {"stent_128x128x256_int16.raw", 148470906.0, 1106473, openvdb::Coord(60, 50, 80), 437.0f},
    };
    for (const Expected& x : scans) {
        const std::string path = eikon::test::sharedData(std::string("volumes/") + x.file);
        const eikon::ScanLayout layout =
            eikon::rawScanLayout(path, std::nullopt, std::nullopt, false);
        const eikon::ScanVolume scan = eikon::readScanVolume(layout, {});
        double sum = 0.0;
        for (auto it = scan.grid->cbeginValueOn(); it; ++it) sum += double(*it);
        CHECK(sum == x.sum);
        CHECK(scan.grid->activeVoxelCount() == openvdb::Index64(x.nonZero));
        CHECK(scan.grid->getConstAccessor().getValue(x.at) == x.value);
    }
}

TEST_CASE("A scan source loads its field through the scene", "[scan]") {
    const std::string volume = eikon::test::sharedData("volumes/LIDC2_256x256x133_uint8.raw");
    const eikon::Scene scene = eikon::parseScene(
        R"({"sources": [{"type": "scan", "file": ")" + volume +
            R"(", "field": "density.ct", "spacing": [0.014, 0.014, 0.025], "origin": [-1.8, -1.8, -1.66],
                "window": [40, 200]}],
            "materials": [{"name": "tissue", "field": "density.ct", "absorption": [1, 2, 3]}]})",
        "ct.json");
    eikon::SceneSources sources(scene);
    eikon::FieldRegistry fields;
    sources.loadFrame(1, fields);
    const eikon::Field& f = fields.get("density.ct");
    CHECK(f.origin == "ct.json:/sources/0");
    const openvdb::Vec3d vs = f.grid->voxelSize();
    CHECK(vs.x() == Approx(0.014));
    CHECK(vs.z() == Approx(0.025));
    const eikon::Bounds3 b = f.activeWorldBounds();
    CHECK(b.min.x >= -1.8f - 0.007f - 1e-4f);
    CHECK(b.max.z <= -1.66f + 132.5f * 0.025f + 1e-4f);
    float maximum = 0.0f;
    for (auto it = openvdb::gridConstPtrCast<openvdb::FloatGrid>(f.grid)->cbeginValueOn(); it; ++it)
        maximum = std::max(maximum, *it);
    CHECK(maximum == 1.0f);
}

TEST_CASE("Scan sources: the scene's errors", "[scan]") {
    const std::string dir = eikon::test::scratchDir("scan_scene_errors");
    writeFile(dir + "/v.nrrd", header("uchar", "raw", "\n") + std::string(24, '\1'));
    auto errorOfScene = [&](const std::string& source) -> std::string {
        try {
            eikon::parseScene(R"({"sources": [)" + source +
                                  R"(], "materials": [{"name": "m", "absorption": [1, 1, 1]}]})",
                              dir + "/s.json");
        } catch (const eikon::Error& e) {
            return e.what();
        }
        return "(no error)";
    };
    CHECK(contains(errorOfScene(R"({"type": "scan", "file": "v.nrrd", "dims": [4, 3, 2]})"),
                   "/sources/0/dims: the NRRD header says how its samples are stored; remove"));
    CHECK(contains(errorOfScene(R"({"type": "scan", "file": "v.raw", "value_type": "uint12"})"),
                   "/sources/0/value_type: expected a value type"));
    CHECK(contains(errorOfScene(R"({"type": "scan", "file": "v.raw", "window": [5, 5]})"),
                   "/sources/0/window/1"));
    CHECK(contains(errorOfScene(R"({"type": "scan", "file": "v.raw", "spacing": [1, 0, 1]})"),
                   "/sources/0/spacing"));
    CHECK(contains(errorOfScene(R"({"type": "scan", "file": "v.raw", "radius": 1})"),
                   "/sources/0/radius: unknown key 'radius' for a scan source"));
    // A missing file is found when the source loads, with the source named.
    const eikon::Scene scene = eikon::parseScene(
        R"({"sources": [{"type": "scan", "file": "gone_4x3x2_uint8.raw"}],
            "materials": [{"name": "m", "absorption": [1, 1, 1]}]})",
        dir + "/s.json");
    eikon::SceneSources sources(scene);
    eikon::FieldRegistry fields;
    CHECK_THROWS_WITH(sources.loadFrame(1, fields),
                      Catch::Contains("gone_4x3x2_uint8.raw: no such file (source " + dir +
                                      "/s.json:/sources/0)"));
}
