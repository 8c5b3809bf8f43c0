#include "sim/ply_header.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "core/printable.h"

namespace eikon {

namespace {

// A header is a few hundred bytes; one that has not ended within a megabyte is not a header.
constexpr std::size_t kMaxHeaderBytes = std::size_t(1) << 20;

struct TypeName {
    const char* name;
    PlyType type;
};

constexpr TypeName kTypeNames[] = {
    {"char", PlyType::Int8},       {"uchar", PlyType::UInt8},    {"short", PlyType::Int16},
    {"ushort", PlyType::UInt16},   {"int", PlyType::Int32},      {"uint", PlyType::UInt32},
    {"float", PlyType::Float32},   {"double", PlyType::Float64}, {"int8", PlyType::Int8},
    {"uint8", PlyType::UInt8},     {"int16", PlyType::Int16},    {"uint16", PlyType::UInt16},
    {"int32", PlyType::Int32},     {"uint32", PlyType::UInt32},  {"float32", PlyType::Float32},
    {"float64", PlyType::Float64},
};

const char* const kTypeList =
    "char, uchar, short, ushort, int, uint, float, double, int8, uint8, int16, uint16, int32, "
    "uint32, float32 or float64";

bool typeNamed(const std::string& name, PlyType& type) {
    for (const TypeName& t : kTypeNames) {
        if (name == t.name) {
            type = t.type;
            return true;
        }
    }
    return false;
}

// Words separated by spaces or tabs.
std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

// Names go back into the canonical header that OpenMesh reads word by word, so they must be one
// word of visible ASCII there too.
bool isPlainName(const std::string& name) {
    return !name.empty() &&
           std::all_of(name.begin(), name.end(), [](char c) { return c > ' ' && c < 0x7f; });
}

std::string quoted(const std::string& text) {
    return "'" + printable(text) + "'";
}

class HeaderParser {
public:
    HeaderParser(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}

    PlyHeader parse() {
        if (bytes_.compare(0, 3, "ply") != 0)
            throw Error(path_, "not a PLY file (it does not start with 'ply')");
        if (!endsHeader()) neverEnds();
        std::string line;
        if (!nextLine(line) || words(line) != std::vector<std::string>{"ply"})
            fail("expected the first line to be 'ply', got " + quoted(line));
        if (!nextLine(line)) neverEnds();
        readFormat(line);
        while (true) {
            if (!nextLine(line)) neverEnds();
            const std::vector<std::string> w = words(line);
            if (w.empty()) continue;
            if (w[0] == "comment" || w[0] == "obj_info") continue;
            if (w[0] == "end_header" && w.size() == 1) break;
            if (w[0] == "element") {
                readElement(w);
            } else if (w[0] == "property") {
                readProperty(w);
            } else {
                fail(
                    "expected 'element', 'property', 'comment', 'obj_info' or 'end_header' "
                    "at the start of a header line, got " +
                    quoted(line));
            }
        }
        for (const PlyElement& e : header_.elements) {
            if (e.count > 0 && e.properties.empty())
                throw Error(path_ + ":" + std::to_string(e.line),
                            "element " + quoted(e.name) + " has " + std::to_string(e.count) +
                                " items but no properties");
        }
        header_.bodyOffset = next_;
        header_.bodyLine = lineNumber_ + 1;
        return std::move(header_);
    }

private:
    // Whether a line of its own says `end_header` within the first megabyte: a header cut short
    // is reported as such, not by the grammar error its last, partial line may make.
    bool endsHeader() {
        const std::size_t start = next_, number = lineNumber_;
        bool found = false;
        for (std::string line; !found && nextLine(line);) {
            const std::vector<std::string> w = words(line);
            found = w.size() == 1 && w[0] == "end_header";
        }
        next_ = start;
        lineNumber_ = number;
        return found;
    }

    // The next line without its line end; false when the header runs out first.
    bool nextLine(std::string& line) {
        if (next_ >= bytes_.size() || next_ > kMaxHeaderBytes) return false;
        std::size_t end = bytes_.find('\n', next_);
        const bool last = end == std::string::npos;
        if (last) end = bytes_.size();
        line = bytes_.substr(next_, end - next_);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        next_ = last ? bytes_.size() : end + 1;
        ++lineNumber_;
        return true;
    }

    [[noreturn]] void fail(const std::string& reason) const {
        throw Error(path_ + ":" + std::to_string(lineNumber_), reason);
    }

    [[noreturn]] void neverEnds() const {
        throw Error(path_,
                    "the PLY header never ends (no 'end_header' line): truncated or corrupt");
    }

    void readFormat(const std::string& line) {
        const std::vector<std::string> w = words(line);
        const char* const form =
            "expected 'format ascii|binary_little_endian|binary_big_endian 1.0', got ";
        if (w.size() != 3 || w[0] != "format") fail(form + quoted(line));
        if (w[1] == "ascii") {
            header_.format = PlyFormat::Ascii;
        } else if (w[1] == "binary_little_endian") {
            header_.format = PlyFormat::BinaryLittleEndian;
        } else if (w[1] == "binary_big_endian") {
            header_.format = PlyFormat::BinaryBigEndian;
        } else {
            fail(form + quoted(line));
        }
        // Version 1.0 is the only PLY there is; "1" and "1.00" say the same.
        const std::string& v = w[2];
        const bool one = v == "1" || (v.size() >= 3 && v.compare(0, 2, "1.") == 0 &&
                                      v.find_first_not_of('0', 2) == std::string::npos);
        if (!one) fail(form + quoted(line) + " (version " + quoted(v) + ")");
    }

    void readElement(const std::vector<std::string>& w) {
        if (w.size() != 3) fail("expected 'element NAME COUNT', got " + quoted(joined(w)));
        if (!isPlainName(w[1])) fail("element name " + quoted(w[1]) + " is not a plain word");
        const std::string& count = w[2];
        // OpenMesh keeps counts in 32 bits; ten digits with no sign or exponent.
        if (count.empty() || count.size() > 10 ||
            count.find_first_not_of("0123456789") != std::string::npos ||
            std::stoull(count) > 0xffffffffull)
            fail("element " + quoted(w[1]) + " count " + quoted(count) +
                 " is not a whole number below 2^32");
        for (const PlyElement& e : header_.elements) {
            if (e.name == w[1]) fail("element " + quoted(w[1]) + " is declared twice");
        }
        PlyElement element;
        element.name = w[1];
        element.count = std::stoull(count);
        element.line = lineNumber_;
        header_.elements.push_back(std::move(element));
    }

    void readProperty(const std::vector<std::string>& w) {
        if (header_.elements.empty())
            fail(
                "a 'property' line before any 'element' line (each property belongs to the "
                "element above it)");
        PlyElement& element = header_.elements.back();
        PlyProperty property;
        property.line = lineNumber_;
        if (w.size() >= 2 && w[1] == "list") {
            if (w.size() != 5)
                fail("expected 'property list COUNT_TYPE ITEM_TYPE NAME', got " +
                     quoted(joined(w)));
            property.isList = true;
            property.countTypeName = w[2];
            property.typeName = w[3];
            property.name = w[4];
            if (!typeNamed(w[2], property.countType) || !plyTypeIsIntegral(property.countType))
                fail("list count type " + quoted(w[2]) +
                     " is not an integer type (char, uchar, short, ushort, int, uint, int8, "
                     "uint8, int16, uint16, int32 or uint32)");
        } else {
            if (w.size() != 3) fail("expected 'property TYPE NAME', got " + quoted(joined(w)));
            property.typeName = w[1];
            property.name = w[2];
        }
        if (!typeNamed(property.typeName, property.type))
            fail("unknown property type " + quoted(property.typeName) + " (expected " + kTypeList +
                 ")");
        if (!isPlainName(property.name))
            fail("property name " + quoted(property.name) + " is not a plain word");
        for (const PlyProperty& p : element.properties) {
            if (p.name == property.name)
                fail("property " + quoted(property.name) + " of element " + quoted(element.name) +
                     " is declared twice");
        }
        element.properties.push_back(std::move(property));
    }

    static std::string joined(const std::vector<std::string>& w) {
        std::string out;
        for (const std::string& s : w) out += (out.empty() ? "" : " ") + s;
        return out;
    }

    const std::string& path_;
    const std::string& bytes_;
    std::size_t next_ = 0;
    std::size_t lineNumber_ = 0;
    PlyHeader header_;
};

}  // namespace

std::size_t plyTypeSize(PlyType type) {
    switch (type) {
        case PlyType::Int8:
        case PlyType::UInt8:
            return 1;
        case PlyType::Int16:
        case PlyType::UInt16:
            return 2;
        case PlyType::Int32:
        case PlyType::UInt32:
        case PlyType::Float32:
            return 4;
        case PlyType::Float64:
            return 8;
    }
    return 0;
}

bool plyTypeIsIntegral(PlyType type) {
    return type != PlyType::Float32 && type != PlyType::Float64;
}

PlyHeader parsePlyHeader(const std::string& path, const std::string& bytes) {
    return HeaderParser(path, bytes).parse();
}

std::string canonicalPlyHeader(const PlyHeader& header) {
    std::string out = "ply\nformat ";
    out += header.format == PlyFormat::Ascii                ? "ascii"
           : header.format == PlyFormat::BinaryLittleEndian ? "binary_little_endian"
                                                            : "binary_big_endian";
    out += " 1.0\n";
    for (const PlyElement& e : header.elements) {
        out += "element " + e.name + " " + std::to_string(e.count) + "\n";
        for (const PlyProperty& p : e.properties) {
            out += "property ";
            if (p.isList) out += "list " + p.countTypeName + " ";
            out += p.typeName + " " + p.name + "\n";
        }
    }
    return out + "end_header\n";
}

}  // namespace eikon
