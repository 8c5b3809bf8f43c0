#include "core/scan_info.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <vector>

#include "core/printable.h"

namespace eikon {
namespace {

const char* encodingName(ScanEncoding e) {
    switch (e) {
        case ScanEncoding::Raw:
            return "raw";
        case ScanEncoding::Gzip:
            return "gzip";
        case ScanEncoding::Ascii:
            return "ascii";
    }
    return "?";
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

std::string vec3Text(const glm::dvec3& v) {
    return number(v.x) + " " + number(v.y) + " " + number(v.z);
}

}  // namespace

bool isScanFile(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".raw" || isNrrdFile(path);
}

std::string formatScanInfo(const std::string& path, const ScanFile& scan) {
    const ScanLayout& l = scan.layout;
    const openvdb::FloatGrid& grid = *scan.volume.grid;
    // Every sample's value: the active voxels, and as many zeros as the grid leaves inactive.
    std::vector<float> values;
    values.reserve(std::size_t(l.sampleCount()));
    for (auto it = grid.cbeginValueOn(); it; ++it) values.push_back(*it);
    const std::size_t zeros = std::size_t(l.sampleCount()) - values.size();
    values.resize(std::size_t(l.sampleCount()), 0.0f);
    std::sort(values.begin(), values.end());
    auto percentile = [&](double p) {
        return values[std::min(values.size() - 1, std::size_t(p / 100.0 * double(values.size())))];
    };

    std::ostringstream out;
    const bool nrrd = isNrrdFile(l.header);
    const std::string order =
        scanValueBytes(l.type) > 1 ? (l.bigEndian ? ", big-endian" : ", little-endian") : "";
    out << printable(path, 400) << ": scanned volume, " << l.describe() << ", "
        << (nrrd ? std::string("NRRD (") + encodingName(l.encoding) + order + ")"
                 : "raw file" + (order.empty() ? "" : " (" + order.substr(2) + ")"))
        << "\n";
    if (l.dataFile != l.header) out << "  samples in " << printable(l.dataFile, 400) << "\n";
    const glm::dvec3 extent = glm::dvec3(l.dims - 1) * l.spacing;
    out << "  spacing " << vec3Text(l.spacing) << ", origin " << vec3Text(l.origin)
        << ", last sample at " << vec3Text(l.origin + extent) << "\n";
    out << "  values " << number(scan.volume.storedMin) << " … " << number(scan.volume.storedMax)
        << "; " << zeros << " of " << l.sampleCount() << " samples are 0 ("
        << number(100.0 * double(zeros) / double(l.sampleCount())) << " %)\n";
    out << "  percentiles: 1 % " << number(percentile(1)) << ", 5 % " << number(percentile(5))
        << ", 25 % " << number(percentile(25)) << ", 50 % " << number(percentile(50)) << ", 75 % "
        << number(percentile(75)) << ", 95 % " << number(percentile(95)) << ", 99 % "
        << number(percentile(99)) << "\n";
    // 16 bins over [min, max]: where the classes are, for a window and transfer functions.
    constexpr int kBins = 16;
    const double lo = scan.volume.storedMin, hi = scan.volume.storedMax;
    const double width = hi > lo ? (hi - lo) / kBins : 1.0;
    std::vector<std::size_t> counts(kBins, 0);
    for (float v : values)
        ++counts[std::size_t(std::clamp(int((double(v) - lo) / width), 0, kBins - 1))];
    const std::size_t most = *std::max_element(counts.begin(), counts.end());
    out << "  histogram (" << kBins << " bins from " << number(lo) << " to " << number(hi)
        << "):\n";
    for (int b = 0; b < kBins; ++b) {
        char line[96];
        std::snprintf(line, sizeof line, "    [%10.4g, %10.4g) %10zu  ", lo + b * width,
                      lo + (b + 1) * width, counts[std::size_t(b)]);
        const int bar = most ? int(40.0 * double(counts[std::size_t(b)]) / double(most) + 0.5) : 0;
        out << line << std::string(std::size_t(bar), '#') << "\n";
    }
    return out.str();
}

}  // namespace eikon
