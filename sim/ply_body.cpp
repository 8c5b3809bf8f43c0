#include "sim/ply_body.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "core/printable.h"

namespace eikon {

namespace {

std::string quoted(const std::string& text) {
    return "'" + printable(text) + "'";
}

std::string itemName(const PlyElement& e, std::uint64_t item) {
    return quoted(e.name) + " item " + std::to_string(item + 1);
}

// The fewest bytes (binary) one item of `e` can take: its scalars and its lists' counts.
std::uint64_t minimumBinaryItemBytes(const PlyElement& e) {
    std::uint64_t bytes = 0;
    for (const PlyProperty& p : e.properties) bytes += plyTypeSize(p.isList ? p.countType : p.type);
    return bytes;
}

// The header's counts against the bytes left, before any item is walked: a count of 4e9 fails
// here at once, with the sizes in the message.
void checkCountFits(const std::string& path, const PlyElement& e, std::uint64_t itemBytes,
                    std::uint64_t available, const char* unit, std::uint64_t slack = 0) {
    if (e.count * itemBytes <= available + slack) return;
    throw Error(path, "element " + quoted(e.name) + " declares " + std::to_string(e.count) +
                          " items, which need at least " + std::to_string(e.count * itemBytes) +
                          " " + unit + ", but the file has " + std::to_string(available) +
                          " bytes left for it: truncated or corrupt");
}

class BinaryWalker {
public:
    BinaryWalker(const std::string& path, const std::string& bytes, const PlyHeader& header)
        : path_(path),
          bytes_(bytes),
          pos_(header.bodyOffset),
          bigEndian_(header.format == PlyFormat::BinaryBigEndian) {}

    void walk(const PlyHeader& header) {
        for (const PlyElement& e : header.elements) {
            checkCountFits(path_, e, minimumBinaryItemBytes(e), bytes_.size() - pos_, "bytes");
            for (std::uint64_t i = 0; i < e.count; ++i)
                for (const PlyProperty& p : e.properties) walkProperty(e, i, p);
        }
    }

private:
    void walkProperty(const PlyElement& e, std::uint64_t item, const PlyProperty& p) {
        if (!p.isList) {
            need(e, item, p, plyTypeSize(p.type));
            pos_ += plyTypeSize(p.type);
            return;
        }
        need(e, item, p, plyTypeSize(p.countType));
        const std::int64_t count = readInteger(p.countType);
        if (count < 0)
            throw Error(path_, itemName(e, item) + " list " + quoted(p.name) + " has count " +
                                   std::to_string(count) + " (at byte " +
                                   std::to_string(pos_ - plyTypeSize(p.countType)) + "): corrupt");
        const std::uint64_t listBytes = std::uint64_t(count) * plyTypeSize(p.type);
        if (listBytes > bytes_.size() - pos_)
            throw Error(path_, itemName(e, item) + " list " + quoted(p.name) + " holds " +
                                   std::to_string(count) + " values, past the end of the file " +
                                   "(at byte " + std::to_string(pos_) + "): truncated or corrupt");
        pos_ += listBytes;
    }

    void need(const PlyElement& e, std::uint64_t item, const PlyProperty& p, std::size_t n) const {
        if (n <= bytes_.size() - pos_) return;
        throw Error(path_, "the file ends inside " + itemName(e, item) + " (property " +
                               quoted(p.name) + "): truncated");
    }

    std::int64_t readInteger(PlyType type) {
        const std::size_t n = plyTypeSize(type);
        unsigned char raw[4] = {0, 0, 0, 0};
        for (std::size_t k = 0; k < n; ++k)
            raw[k] = static_cast<unsigned char>(bytes_[pos_ + (bigEndian_ ? n - 1 - k : k)]);
        pos_ += n;
        std::uint32_t u = 0;
        for (std::size_t k = 0; k < n; ++k) u |= std::uint32_t(raw[k]) << (8 * k);
        switch (type) {
            case PlyType::Int8:
                return std::int8_t(u);
            case PlyType::Int16:
                return std::int16_t(u);
            case PlyType::Int32:
                return std::int32_t(u);
            default:
                return std::int64_t(u);
        }
    }

    const std::string& path_;
    const std::string& bytes_;
    std::size_t pos_;
    bool bigEndian_;
};

class AsciiWalker {
public:
    AsciiWalker(const std::string& path, const std::string& bytes, const PlyHeader& header)
        : path_(path), bytes_(bytes), pos_(header.bodyOffset), line_(header.bodyLine) {}

    void walk(const PlyHeader& header) {
        for (const PlyElement& e : header.elements) {
            // Every value is at least one character and a separator (the last one's may be the
            // end of the file, hence the one byte of slack).
            checkCountFits(path_, e, 2 * e.properties.size(), bytes_.size() - pos_,
                           "bytes (two per value)", 1);
            for (std::uint64_t i = 0; i < e.count; ++i)
                for (const PlyProperty& p : e.properties) walkProperty(e, i, p);
        }
    }

private:
    void walkProperty(const PlyElement& e, std::uint64_t item, const PlyProperty& p) {
        if (!p.isList) {
            checkValue(e, item, p, p.type, token(e, item, p));
            return;
        }
        const std::string count = token(e, item, p);
        if (count.empty() || count.size() > 10 ||
            count.find_first_not_of("0123456789") != std::string::npos ||
            std::stoull(count) > 0xffffffffull)
            fail(itemName(e, item) + " list " + quoted(p.name) + ": expected a count, got " +
                 quoted(count));
        // Each value takes a byte and a separator: a count the rest of the file cannot hold
        // fails here rather than after walking to the end.
        const std::uint64_t n = std::stoull(count);
        if (n > (bytes_.size() - pos_ + 1) / 2)
            fail(itemName(e, item) + " list " + quoted(p.name) + " has count " + count +
                 ", more values than the rest of the file holds: truncated or corrupt");
        for (std::uint64_t k = 0; k < n; ++k) checkValue(e, item, p, p.type, token(e, item, p));
    }

    void checkValue(const PlyElement& e, std::uint64_t item, const PlyProperty& p, PlyType type,
                    const std::string& text) const {
        if (plyTypeIsIntegral(type)) {
            const std::size_t digits = (text[0] == '-' || text[0] == '+') ? 1 : 0;
            if (text.size() > digits &&
                text.find_first_not_of("0123456789", digits) == std::string::npos)
                return;
            fail(itemName(e, item) + " property " + quoted(p.name) + ": expected an integer, got " +
                 quoted(text));
        }
        // What `>> float` reads: digits, sign, point, exponent; no nan, inf or hex.
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        const bool plain = text.find_first_not_of("0123456789+-.eE") == std::string::npos;
        if (plain && end == text.c_str() + text.size() && std::fabs(x) <= double(FLT_MAX)) return;
        fail(itemName(e, item) + " property " + quoted(p.name) +
             ": expected a finite number a float can hold, got " + quoted(text));
    }

    // The next whitespace-separated value.
    std::string token(const PlyElement& e, std::uint64_t item, const PlyProperty& p) {
        while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
            if (bytes_[pos_] == '\n') ++line_;
            ++pos_;
        }
        if (pos_ >= bytes_.size())
            throw Error(path_, "the file ends before " + itemName(e, item) + " (property " +
                                   quoted(p.name) + "): truncated");
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_])))
            ++pos_;
        return bytes_.substr(start, pos_ - start);
    }

    [[noreturn]] void fail(const std::string& reason) const {
        throw Error(path_ + ":" + std::to_string(line_), reason);
    }

    const std::string& path_;
    const std::string& bytes_;
    std::size_t pos_;
    std::size_t line_;
};

}  // namespace

void checkPlyBody(const std::string& path, const std::string& bytes, const PlyHeader& header) {
    if (header.format == PlyFormat::Ascii) {
        AsciiWalker(path, bytes, header).walk(header);
    } else {
        BinaryWalker(path, bytes, header).walk(header);
    }
}

}  // namespace eikon
