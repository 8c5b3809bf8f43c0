#pragma once
// Where the samples of a scanned volume (CT, MRI, a simulation's dump) are and how they are
// stored: from an NRRD header (teem's format, what 3D Slicer, ITK and the SciVis collections
// write), or from the name of a headerless raw file (`engine_256x256x128_uint8.raw`, the
// convention of the Open SciVis Datasets). core/scan_volume.h reads the samples it describes.
#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace eikon {

enum class ScanValueType {
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Int64,
    UInt64,
    Float32,
    Float64
};

int scanValueBytes(ScanValueType type);
// Our spelling: "uint8", "int16", "float32", ...
std::string scanValueTypeName(ScanValueType type);
// Ours and NRRD's spellings ("uchar", "unsigned short", "float", "double", "int16_t", ...);
// nullopt for anything else.
std::optional<ScanValueType> parseScanValueType(const std::string& name);

enum class ScanEncoding {
    Raw,    // the samples' bytes as they are
    Gzip,   // the same bytes through gzip (NRRD's "gzip"/"gz")
    Ascii,  // numbers as text, separated by white space or commas (NRRD's "ascii"/"text"/"txt")
};

struct ScanLayout {
    glm::ivec3 dims{0};  // samples along x (fastest), y, z
    ScanValueType type = ScanValueType::UInt8;
    bool bigEndian = false;
    ScanEncoding encoding = ScanEncoding::Raw;
    glm::dvec3 spacing{1.0};  // scene units between neighbouring samples, per axis
    glm::dvec3 origin{0.0};   // the position of sample (0, 0, 0)
    std::string dataFile;     // the file holding the samples (the header itself when attached)
    // Bytes before the samples in dataFile (for Gzip: the start of the compressed stream).
    std::int64_t dataOffset = 0;
    // Bytes to skip after decompression (NRRD's "byte skip"); −1: the raw samples end the file.
    std::int64_t byteSkip = 0;
    std::string header;  // the file the layout was read from, named in messages

    std::int64_t sampleCount() const { return std::int64_t(dims.x) * dims.y * dims.z; }
    std::int64_t sampleBytes() const { return sampleCount() * scanValueBytes(type); }
    // "256×256×128 uint8"
    std::string describe() const;
};

// The most samples along one axis a scan may have: 4096 (a 4096³ float volume is 256 GiB, and a
// size beyond it in a header is far likelier a corrupt file than a scan).
constexpr int kMaxScanSamplesAcross = 4096;

// True when `path` starts with NRRD's magic ("NRRD000" and a version digit).
bool isNrrdFile(const std::string& path);

// The layout an NRRD header (attached data, .nrrd, or detached, .nhdr with "data file") gives.
// Reads three-dimensional volumes of the scalar types above in raw, gzip or ascii encoding, with
// "spacings" or axis-aligned "space directions", "space origin", "byte skip", "line skip" and
// "endian". Throws eikon::Error(path, reason) for a file that is not NRRD or not one of these,
// naming the field at fault: a missing or malformed "sizes", an unknown type, an encoding other
// than those (bzip2, hex), a dimension other than 3, several data files.
ScanLayout readNrrdHeader(const std::string& path);

// The layout of a headerless raw file: little-endian (unless `bigEndian`), spacing 1, its
// dimensions and type from `dims` and `type`, or where those are not given from its name
// (`<name>_<X>x<Y>x<Z>_<type>.raw`). Throws eikon::Error(path, reason) when neither says.
ScanLayout rawScanLayout(const std::string& path, std::optional<glm::ivec3> dims,
                         std::optional<ScanValueType> type, bool bigEndian);

}  // namespace eikon
