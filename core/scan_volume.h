#pragma once
// Reads the samples of a scanned volume (core/scan_layout.h says where they are) into an OpenVDB
// float grid, so that the rest of eikon sees an ordinary field: sample (i, j, k) is voxel
// (i, j, k), placed at origin + (i, j, k)·spacing. Samples that are exactly 0 stay inactive
// background; everything else is an active voxel.
#include <optional>
#include <string>

#include <openvdb/openvdb.h>

#include "core/scan_layout.h"

namespace eikon {

// Maps stored values linearly so that `low` becomes 0 and `high` 1, clamped to [0, 1]: CT's
// window (Hounsfield units or a scanner's raw counts to an amount a material reads).
struct ScanWindow {
    double low = 0.0;
    double high = 1.0;
};

struct ScanReadOptions {
    std::optional<ScanWindow> window;
    // The field the grid becomes: its name for messages, and whether its values must be >= 0
    // (fieldMustBeNonNegative: density, n, kappa, sigma, flame).
    std::string fieldName = "density";
};

struct ScanVolume {
    openvdb::FloatGrid::Ptr grid;
    double storedMin = 0.0;  // the samples as stored, before the window
    double storedMax = 0.0;
};

// An upper bound of the memory one sample takes while it is read (the float grid's leaves and
// their masks, the slice being decoded) and written out again by `eikon convert`, checked against
// eikon's memory limit before reading. Measured: 7.5 B a sample (peak RSS of `eikon convert`,
// 113 MB for the 8.4 M samples of the engine scan against 62 MB for the tooth's 1.6 M).
constexpr double kScanBytesPerSample = 12.0;

// Throws eikon::Error(file, reason) for a data file that is missing, holds fewer or more samples
// than the layout says (the byte counts named), a corrupt gzip stream, ascii text that is not
// numbers, a NaN or infinite sample, a negative value for a field that must not be negative (the
// sample's position named, the window suggested), or a volume over the memory limit.
ScanVolume readScanVolume(const ScanLayout& layout, const ScanReadOptions& options);

// What a scene's scan source and `eikon convert` ask of a file.
struct ScanFileOptions {
    // Headerless raw files only (an NRRD header says them: giving one is an error): dimensions and
    // value type, else from the file's name; byte order.
    std::optional<glm::ivec3> dims;
    std::optional<ScanValueType> type;
    bool bigEndian = false;
    // Replace the header's (or the raw default of spacing 1 at the origin).
    std::optional<glm::dvec3> spacing;
    std::optional<glm::dvec3> origin;
    ScanReadOptions read;
};

struct ScanFile {
    ScanLayout layout;
    ScanVolume volume;
};

// An NRRD file (told by its content) or a raw file, read with `options`. Throws eikon::Error as
// readNrrdHeader, rawScanLayout and readScanVolume do.
ScanFile readScanFile(const std::string& path, const ScanFileOptions& options);
// "tooth_103x94x161_uint8.raw: 103×94×161 uint8, values 0 … 255, into field 'density'"
std::string describeScanFile(const std::string& path, const ScanFile& scan);

}  // namespace eikon
