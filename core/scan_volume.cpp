#include "core/scan_volume.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include "core/error.h"
#include "core/field_registry.h"
#include "core/memory_limit.h"
#include "core/printable.h"
#include "core/vdb_import.h"

namespace fs = std::filesystem;

namespace eikon {
namespace {

// Bytes of samples, from a file as they are or through gzip. read() returns how many it got.
class ByteSource {
public:
    virtual ~ByteSource() = default;
    virtual std::size_t read(char* out, std::size_t n) = 0;
};

class RawSource : public ByteSource {
public:
    RawSource(const std::string& file, std::int64_t offset) : in_(file, std::ios::binary) {
        in_.seekg(offset);
    }
    std::size_t read(char* out, std::size_t n) override {
        in_.read(out, std::streamsize(n));
        return std::size_t(in_.gcount());
    }

private:
    std::ifstream in_;
};

class GzipSource : public ByteSource {
public:
    GzipSource(const std::string& file, std::int64_t offset) : file_(file) {
        const int fd = ::open(file.c_str(), O_RDONLY);
        if (fd < 0) throw Error(file, "cannot be opened");
        // gzdopen reads the stream from the descriptor's position: the end of the header.
        if (::lseek(fd, offset, SEEK_SET) != offset || !(gz_ = gzdopen(fd, "rb"))) {
            ::close(fd);
            throw Error(file, "cannot be opened as a gzip stream");
        }
    }
    ~GzipSource() override { gzclose(gz_); }
    std::size_t read(char* out, std::size_t n) override {
        std::size_t got = 0;
        while (got < n) {
            const unsigned chunk = unsigned(std::min<std::size_t>(n - got, 1u << 30));
            const int r = gzread(gz_, out + got, chunk);
            if (r < 0) {
                int code = 0;
                throw Error(file_,
                            std::string("corrupt gzip stream (zlib: ") + gzerror(gz_, &code) + ")");
            }
            if (r == 0) break;
            got += std::size_t(r);
        }
        return got;
    }

private:
    std::string file_;
    gzFile gz_ = nullptr;
};

template <typename T>
T decode(const unsigned char* bytes, bool bigEndian) {
    unsigned char b[sizeof(T)];
    for (std::size_t i = 0; i < sizeof(T); ++i)
        b[i] = bigEndian ? bytes[sizeof(T) - 1 - i] : bytes[i];  // this machine is little-endian
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
}

double decodeSample(ScanValueType type, const unsigned char* bytes, bool bigEndian) {
    switch (type) {
        case ScanValueType::Int8:
            return decode<std::int8_t>(bytes, bigEndian);
        case ScanValueType::UInt8:
            return decode<std::uint8_t>(bytes, bigEndian);
        case ScanValueType::Int16:
            return decode<std::int16_t>(bytes, bigEndian);
        case ScanValueType::UInt16:
            return decode<std::uint16_t>(bytes, bigEndian);
        case ScanValueType::Int32:
            return decode<std::int32_t>(bytes, bigEndian);
        case ScanValueType::UInt32:
            return decode<std::uint32_t>(bytes, bigEndian);
        case ScanValueType::Int64:
            return double(decode<std::int64_t>(bytes, bigEndian));
        case ScanValueType::UInt64:
            return double(decode<std::uint64_t>(bytes, bigEndian));
        case ScanValueType::Float32:
            return decode<float>(bytes, bigEndian);
        case ScanValueType::Float64:
            return decode<double>(bytes, bigEndian);
    }
    return 0.0;
}

std::string position(const glm::ivec3& ijk) {
    return "(" + std::to_string(ijk.x) + ", " + std::to_string(ijk.y) + ", " +
           std::to_string(ijk.z) + ")";
}

std::string formatNumber(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

// Takes the samples one z-slice at a time, in file order, into the grid.
class GridWriter {
public:
    GridWriter(const ScanLayout& layout, const ScanReadOptions& options)
        : layout_(layout),
          options_(options),
          grid_(openvdb::FloatGrid::create(0.0f)),
          accessor_(grid_->tree()) {
        // OpenVDB throws ArithmeticError for a scale near zero: the readers refuse such spacings
        // (scan_layout.cpp); a layout made by hand is refused here.
        for (int a = 0; a < 3; ++a)
            if (!(layout.spacing[a] >= 1e-6 && layout.spacing[a] <= 1e6))
                throw Error(layout.header, "a spacing of " + formatNumber(layout.spacing[a]) +
                                               " between samples (eikon takes 1e-6 to 1e6)");
        openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(1.0);
        xform->preScale(openvdb::Vec3d(layout.spacing.x, layout.spacing.y, layout.spacing.z));
        xform->postTranslate(openvdb::Vec3d(layout.origin.x, layout.origin.y, layout.origin.z));
        grid_->setTransform(xform);
        grid_->setName(options.fieldName);
        grid_->setGridClass(openvdb::GRID_FOG_VOLUME);
    }

    void add(double stored) {
        const glm::ivec3 ijk(int(next_ % layout_.dims.x),
                             int((next_ / layout_.dims.x) % layout_.dims.y),
                             int(next_ / (std::int64_t(layout_.dims.x) * layout_.dims.y)));
        ++next_;
        if (!std::isfinite(stored))
            throw Error(layout_.dataFile, "the sample at " + position(ijk) + " is " +
                                              formatNumber(stored) + " (NaN or infinite)");
        storedMin_ = std::min(storedMin_, stored);
        storedMax_ = std::max(storedMax_, stored);
        double v = stored;
        if (options_.window) {
            const ScanWindow& w = *options_.window;
            v = std::clamp((stored - w.low) / (w.high - w.low), 0.0, 1.0);
        }
        if (v < 0.0 && fieldMustBeNonNegative(options_.fieldName))
            throw Error(layout_.dataFile,
                        "the sample at " + position(ijk) + " is " + formatNumber(v) +
                            ", and field '" + options_.fieldName +
                            "' must not be negative: map the scan's values to [0, 1] with "
                            "\"window\": [low, high]");
        const float f = float(v);
        if (f != 0.0f) accessor_.setValue(openvdb::Coord(ijk.x, ijk.y, ijk.z), f);
    }

    ScanVolume finish() {
        ScanVolume out;
        out.grid = grid_;
        out.storedMin = storedMin_;
        out.storedMax = storedMax_;
        return out;
    }

private:
    const ScanLayout& layout_;
    const ScanReadOptions& options_;
    openvdb::FloatGrid::Ptr grid_;
    openvdb::FloatGrid::Accessor accessor_;
    std::int64_t next_ = 0;
    double storedMin_ = std::numeric_limits<double>::max();
    double storedMax_ = std::numeric_limits<double>::lowest();
};

std::string sizeMismatch(const ScanLayout& layout, std::int64_t held, const std::string& of) {
    return "holds " + std::to_string(held) + " bytes of samples" + of + ", and " +
           layout.describe() + " is " + std::to_string(layout.sampleBytes()) +
           " bytes: " + (held < layout.sampleBytes() ? "the file is truncated, or " : "") +
           "its dimensions or value type do not match the file";
}

void readBinary(const ScanLayout& layout, GridWriter& writer) {
    std::error_code ec;
    const std::int64_t fileBytes = std::int64_t(fs::file_size(layout.dataFile, ec));
    if (ec) throw Error(layout.dataFile, "cannot be read");
    std::unique_ptr<ByteSource> source;
    if (layout.encoding == ScanEncoding::Raw) {
        std::int64_t offset = layout.dataOffset + std::max<std::int64_t>(0, layout.byteSkip);
        if (layout.byteSkip == -1)
            offset = std::max<std::int64_t>(0, fileBytes - layout.sampleBytes());
        const std::int64_t held = std::max<std::int64_t>(0, fileBytes - offset);
        if (held != layout.sampleBytes())
            throw Error(
                layout.dataFile,
                sizeMismatch(
                    layout, held,
                    offset > 0 ? " after its first " + std::to_string(offset) + " bytes" : ""));
        source = std::make_unique<RawSource>(layout.dataFile, offset);
    } else {
        source = std::make_unique<GzipSource>(layout.dataFile, layout.dataOffset);
        std::vector<char> skipped(std::size_t(std::min<std::int64_t>(layout.byteSkip, 1 << 20)));
        for (std::int64_t left = layout.byteSkip; left > 0;) {
            const std::size_t n =
                std::size_t(std::min<std::int64_t>(left, std::int64_t(skipped.size())));
            if (source->read(skipped.data(), n) != n)
                throw Error(layout.dataFile, "its gzip stream ends within the \"byte skip\"");
            left -= std::int64_t(n);
        }
    }
    const int bytes = scanValueBytes(layout.type);
    const std::size_t sliceBytes = std::size_t(layout.dims.x) * layout.dims.y * bytes;
    std::vector<unsigned char> slice(sliceBytes);
    for (int k = 0; k < layout.dims.z; ++k) {
        const std::size_t got = source->read(reinterpret_cast<char*>(slice.data()), sliceBytes);
        if (got != sliceBytes)
            throw Error(
                layout.dataFile,
                sizeMismatch(layout, std::int64_t(k) * std::int64_t(sliceBytes) + std::int64_t(got),
                             layout.encoding == ScanEncoding::Gzip ? " once unzipped" : ""));
        for (std::size_t s = 0; s < sliceBytes; s += std::size_t(bytes))
            writer.add(decodeSample(layout.type, slice.data() + s, layout.bigEndian));
    }
    if (layout.encoding == ScanEncoding::Gzip) {
        // Read on to the stream's end, where zlib checks its CRC: a stream corrupted in its
        // last bytes fails there, and one longer than the samples is a layout that does not match.
        char extra[4096];
        if (source->read(extra, sizeof(extra)) > 0)
            throw Error(layout.dataFile, "its gzip stream holds more than the " +
                                             std::to_string(layout.sampleBytes()) + " bytes of " +
                                             layout.describe() +
                                             ": its dimensions or value type do not match");
    }
}

// NRRD's ascii encoding: numbers separated by white space (and, as teem writes some, commas).
void readAscii(const ScanLayout& layout, GridWriter& writer) {
    std::ifstream in(layout.dataFile, std::ios::binary);
    in.seekg(layout.dataOffset);
    std::int64_t count = 0;
    std::string token;
    auto nextToken = [&]() -> bool {
        token.clear();
        char c;
        while (in.get(c)) {
            const bool separator = std::isspace(static_cast<unsigned char>(c)) || c == ',';
            if (separator) {
                if (!token.empty()) return true;
                continue;
            }
            token.push_back(c);
            if (token.size() > 64)
                throw Error(layout.dataFile, "sample " + std::to_string(count) + " (\"" +
                                                 printable(token) + "\") is not a number");
        }
        return !token.empty();
    };
    while (count < layout.sampleCount()) {
        if (!nextToken())
            throw Error(layout.dataFile, "holds " + std::to_string(count) + " samples, and " +
                                             layout.describe() + " is " +
                                             std::to_string(layout.sampleCount()) +
                                             ": the file is truncated, or its sizes do not match");
        std::size_t used = 0;
        double v = 0.0;
        try {
            v = std::stod(token, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != token.size())
            throw Error(layout.dataFile, "sample " + std::to_string(count) + " (\"" +
                                             printable(token) + "\") is not a number");
        writer.add(v);
        ++count;
    }
    if (nextToken())
        throw Error(layout.dataFile, "holds more than the " + std::to_string(layout.sampleCount()) +
                                         " samples of " + layout.describe() +
                                         ": its sizes do not match the file");
}

}  // namespace

ScanVolume readScanVolume(const ScanLayout& layout, const ScanReadOptions& options) {
    ensureOpenVdbInitialized();
    std::error_code ec;
    if (!fs::is_regular_file(layout.dataFile, ec)) throw Error(layout.dataFile, "no such file");
    if (options.window && !(options.window->high > options.window->low))
        throw Error(layout.header, "a window needs high > low");
    checkMemory(layout.header, double(layout.sampleCount()) * kScanBytesPerSample,
                "the scan's " + layout.describe() + " samples", "crop or downsample the scan");
    GridWriter writer(layout, options);
    if (layout.encoding == ScanEncoding::Ascii)
        readAscii(layout, writer);
    else
        readBinary(layout, writer);
    return writer.finish();
}

ScanFile readScanFile(const std::string& path, const ScanFileOptions& options) {
    ScanFile scan;
    if (isNrrdFile(path)) {
        if (options.dims || options.type || options.bigEndian)
            throw Error(path,
                        "an NRRD header says how its samples are stored; the dimensions, "
                        "value type and byte order are for headerless raw files");
        scan.layout = readNrrdHeader(path);
    } else {
        scan.layout = rawScanLayout(path, options.dims, options.type, options.bigEndian);
    }
    if (options.spacing) scan.layout.spacing = *options.spacing;
    if (options.origin) scan.layout.origin = *options.origin;
    scan.volume = readScanVolume(scan.layout, options.read);
    return scan;
}

std::string describeScanFile(const std::string& path, const ScanFile& scan) {
    std::ostringstream out;
    out << path << ": " << scan.layout.describe() << ", values " << scan.volume.storedMin << " … "
        << scan.volume.storedMax << ", into field '" << scan.volume.grid->getName() << "'";
    return out.str();
}

}  // namespace eikon
