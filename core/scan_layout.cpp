#include "core/scan_layout.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "core/log.h"
#include "core/printable.h"

namespace fs = std::filesystem;

namespace eikon {
namespace {

struct TypeSpelling {
    const char* name;
    ScanValueType type;
};

// NRRD's spellings (teem's airEnum for nrrdType) and the SciVis collection's, one table.
constexpr TypeSpelling kTypeSpellings[] = {
    {"int8", ScanValueType::Int8},
    {"int8_t", ScanValueType::Int8},
    {"signed char", ScanValueType::Int8},
    {"uint8", ScanValueType::UInt8},
    {"uint8_t", ScanValueType::UInt8},
    {"uchar", ScanValueType::UInt8},
    {"unsigned char", ScanValueType::UInt8},
    {"int16", ScanValueType::Int16},
    {"int16_t", ScanValueType::Int16},
    {"short", ScanValueType::Int16},
    {"short int", ScanValueType::Int16},
    {"signed short", ScanValueType::Int16},
    {"signed short int", ScanValueType::Int16},
    {"uint16", ScanValueType::UInt16},
    {"uint16_t", ScanValueType::UInt16},
    {"ushort", ScanValueType::UInt16},
    {"unsigned short", ScanValueType::UInt16},
    {"unsigned short int", ScanValueType::UInt16},
    {"int32", ScanValueType::Int32},
    {"int32_t", ScanValueType::Int32},
    {"int", ScanValueType::Int32},
    {"signed int", ScanValueType::Int32},
    {"uint32", ScanValueType::UInt32},
    {"uint32_t", ScanValueType::UInt32},
    {"uint", ScanValueType::UInt32},
    {"unsigned int", ScanValueType::UInt32},
    {"int64", ScanValueType::Int64},
    {"int64_t", ScanValueType::Int64},
    {"longlong", ScanValueType::Int64},
    {"long long", ScanValueType::Int64},
    {"long long int", ScanValueType::Int64},
    {"signed long long", ScanValueType::Int64},
    {"signed long long int", ScanValueType::Int64},
    {"uint64", ScanValueType::UInt64},
    {"uint64_t", ScanValueType::UInt64},
    {"ulonglong", ScanValueType::UInt64},
    {"unsigned long long", ScanValueType::UInt64},
    {"unsigned long long int", ScanValueType::UInt64},
    {"float32", ScanValueType::Float32},
    {"float", ScanValueType::Float32},
    {"float64", ScanValueType::Float64},
    {"double", ScanValueType::Float64},
};

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Longest header line and header eikon reads: a real header is a few hundred bytes, and a
// binary file mistaken for one must not be read line by line into memory.
constexpr std::size_t kMaxHeaderLine = 64 * 1024;
constexpr std::size_t kMaxHeaderBytes = 1024 * 1024;

class NrrdFields {
public:
    NrrdFields(std::string path) : path_(std::move(path)) {}
    void add(const std::string& key, const std::string& value) { fields_[lower(key)] = value; }
    const std::string* find(const std::string& key) const {
        auto it = fields_.find(key);
        return it == fields_.end() ? nullptr : &it->second;
    }
    const std::string& required(const std::string& key) const {
        if (const std::string* v = find(key)) return *v;
        throw Error(path_, "the NRRD header has no \"" + key + "\" field");
    }
    [[noreturn]] void fail(const std::string& key, const std::string& expected) const {
        const std::string* value = find(key);  // null for a key the header spells otherwise
        throw Error(path_, "NRRD field \"" + key + "\": expected " + expected + ", got \"" +
                               (value ? printable(*value) : std::string()) + "\"");
    }

private:
    std::string path_;
    std::map<std::string, std::string> fields_;
};

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

bool parseInteger(const std::string& text, std::int64_t& out) {
    if (text.empty()) return false;
    std::size_t used = 0;
    try {
        out = std::stoll(text, &used);
    } catch (const std::exception&) {
        return false;
    }
    return used == text.size();
}

bool parseReal(const std::string& text, double& out) {
    std::size_t used = 0;
    try {
        out = std::stod(text, &used);
    } catch (const std::exception&) {
        return false;
    }
    return used == text.size() && std::isfinite(out);
}

glm::ivec3 readSizes(const NrrdFields& fields) {
    const std::vector<std::string> sizes = words(fields.required("sizes"));
    if (sizes.size() != 3) fields.fail("sizes", "three sizes");
    glm::ivec3 dims;
    for (int a = 0; a < 3; ++a) {
        std::int64_t n = 0;
        if (!parseInteger(sizes[a], n) || n < 1 || n > kMaxScanSamplesAcross)
            fields.fail("sizes",
                        "three integers in [1, " + std::to_string(kMaxScanSamplesAcross) + "]");
        dims[a] = int(n);
    }
    return dims;
}

// Spacings eikon takes, scene units between samples: OpenVDB refuses a transform whose scale is
// within its tolerance of zero (ArithmeticError, found by fuzz_nrrd with a 5e-30 spacing), and
// beyond 1e6 a scan's extent leaves float.
constexpr double kMinScanSpacing = 1e-6;
constexpr double kMaxScanSpacing = 1e6;

// "(1.4,0,0) (0,1.4,0) (0,0,2.5)": each axis's step in space. Their lengths are the spacing; an
// axis that is not along x, y, z (an oblique scan) or points backwards (a flip) is placed along
// its own axis, said once, since the render volume is axis-aligned.
glm::dvec3 readSpaceDirections(const NrrdFields& fields, const std::string& path) {
    const std::string expected = "three vectors such as (1.4,0,0) (0,1.4,0) (0,0,2.5)";
    const std::string& text = fields.required("space directions");
    std::vector<std::string> vectors;
    for (std::size_t at = 0; (at = text.find('(', at)) != std::string::npos;) {
        const std::size_t end = text.find(')', at);
        if (end == std::string::npos) fields.fail("space directions", expected);
        vectors.push_back(text.substr(at + 1, end - at - 1));
        at = end;
    }
    if (vectors.size() != 3) fields.fail("space directions", expected);
    glm::dvec3 spacing;
    bool reoriented = false;
    for (int a = 0; a < 3; ++a) {
        std::array<double, 3> v{};
        std::istringstream in(vectors[a]);
        std::string part;
        for (int c = 0; c < 3; ++c) {
            if (!std::getline(in, part, ',') || !parseReal(trim(part), v[c]))
                fields.fail("space directions", expected);
        }
        spacing[a] = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(spacing[a] >= kMinScanSpacing && spacing[a] <= kMaxScanSpacing))
            fields.fail("space directions", "vectors 1e-6 to 1e6 long");
        reoriented |= v[a] <= 0.0 || std::abs(v[a]) < spacing[a] * (1.0 - 1e-9);
    }
    if (reoriented)
        logWarning(path +
                   ": the scan's axes are rotated or flipped in space (\"space directions\"); "
                   "eikon places sample axis i along scene axis i with the spacings they give");
    return spacing;
}

glm::dvec3 readSpacings(const NrrdFields& fields) {
    const std::vector<std::string> parts = words(fields.required("spacings"));
    if (parts.size() != 3) fields.fail("spacings", "three spacings");
    glm::dvec3 spacing;
    for (int a = 0; a < 3; ++a) {
        // NaN marks a non-spatial axis in NRRD; all three axes of a volume are spatial.
        if (!parseReal(parts[a], spacing[a]) ||
            !(spacing[a] >= kMinScanSpacing && spacing[a] <= kMaxScanSpacing))
            fields.fail("spacings", "three numbers from 1e-6 to 1e6");
    }
    return spacing;
}

glm::dvec3 readSpaceOrigin(const NrrdFields& fields) {
    std::string text = trim(fields.required("space origin"));
    const std::string expected = "a vector such as (0,0,0)";
    if (text.size() < 2 || text.front() != '(' || text.back() != ')')
        fields.fail("space origin", expected);
    std::istringstream in(text.substr(1, text.size() - 2));
    glm::dvec3 origin;
    std::string part;
    for (int c = 0; c < 3; ++c)
        if (!std::getline(in, part, ',') || !parseReal(trim(part), origin[c]))
            fields.fail("space origin", expected);
    return origin;
}

std::int64_t readSkip(const NrrdFields& fields, const std::string& key, std::int64_t lowest) {
    const std::string* text = fields.find(key);
    if (!text) return 0;
    std::int64_t n = 0;
    if (!parseInteger(trim(*text), n) || n < lowest)
        fields.fail(key, "an integer >= " + std::to_string(lowest));
    return n;
}

ScanEncoding readEncoding(const NrrdFields& fields) {
    const std::string e = lower(trim(fields.required("encoding")));
    if (e == "raw") return ScanEncoding::Raw;
    if (e == "gzip" || e == "gz") return ScanEncoding::Gzip;
    if (e == "ascii" || e == "text" || e == "txt") return ScanEncoding::Ascii;
    fields.fail("encoding",
                "raw, gzip or ascii (bzip2 and hex are not read; `unu save -e raw` converts)");
}

// Bytes after `offset` in `file` past `lines` newlines: NRRD's "line skip".
std::int64_t skipLines(const std::string& file, std::int64_t offset, std::int64_t lines) {
    if (lines == 0) return offset;
    std::ifstream in(file, std::ios::binary);
    in.seekg(offset);
    for (std::int64_t l = 0; l < lines; ++l) {
        in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
        if (!in) throw Error(file, "ends within the " + std::to_string(lines) + " lines to skip");
    }
    return std::int64_t(in.tellg());
}

}  // namespace

int scanValueBytes(ScanValueType type) {
    switch (type) {
        case ScanValueType::Int8:
        case ScanValueType::UInt8:
            return 1;
        case ScanValueType::Int16:
        case ScanValueType::UInt16:
            return 2;
        case ScanValueType::Int32:
        case ScanValueType::UInt32:
        case ScanValueType::Float32:
            return 4;
        case ScanValueType::Int64:
        case ScanValueType::UInt64:
        case ScanValueType::Float64:
            return 8;
    }
    return 1;
}

std::string scanValueTypeName(ScanValueType type) {
    for (const TypeSpelling& s : kTypeSpellings)
        if (s.type == type) return s.name;  // the first spelling of each type is ours
    return "?";
}

std::optional<ScanValueType> parseScanValueType(const std::string& name) {
    const std::string key = lower(trim(name));
    for (const TypeSpelling& s : kTypeSpellings)
        if (key == s.name) return s.type;
    return std::nullopt;
}

std::string ScanLayout::describe() const {
    return std::to_string(dims.x) + "×" + std::to_string(dims.y) + "×" + std::to_string(dims.z) +
           " " + scanValueTypeName(type);
}

bool isNrrdFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[8] = {};
    if (!in.read(magic, 8)) return false;
    return std::string(magic, 7) == "NRRD000" && std::isdigit(static_cast<unsigned char>(magic[7]));
}

ScanLayout readNrrdHeader(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw Error(path, "no such file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, "cannot be opened");
    if (!isNrrdFile(path))
        throw Error(path, "not an NRRD file (it does not start with NRRD0001 … NRRD0005)");

    NrrdFields fields(path);
    std::string line;
    std::getline(in, line);  // the magic
    std::size_t headerBytes = line.size() + 1;
    bool attachedData = false;
    while (true) {
        line.clear();
        char c;
        while (in.get(c) && c != '\n') {
            line.push_back(c);
            if (line.size() > kMaxHeaderLine)
                throw Error(path, "a header line longer than 64 KiB: not an NRRD header");
        }
        const bool atEnd = !in;
        headerBytes += line.size() + 1;
        if (headerBytes > kMaxHeaderBytes)
            throw Error(path, "a header longer than 1 MiB: not an NRRD header");
        const std::string text = trim(line);
        if (text.empty()) {
            attachedData = !atEnd;  // a blank line ends the header; samples follow
            break;
        }
        if (text[0] == '#') {
            if (atEnd) break;
            continue;
        }
        if (text.find(":=") != std::string::npos) {  // key/value pairs: free-form metadata
            if (atEnd) break;
            continue;
        }
        const std::size_t colon = text.find(": ");
        if (colon == std::string::npos)
            throw Error(path, "NRRD header line \"" + printable(text) +
                                  "\" is neither \"field: value\" nor a comment");
        fields.add(trim(text.substr(0, colon)), trim(text.substr(colon + 2)));
        if (atEnd) break;
    }

    ScanLayout layout;
    layout.header = path;
    const std::string& typeText = fields.required("type");
    const auto type = parseScanValueType(typeText);
    if (!type) fields.fail("type", "a scalar type (uchar, short, ushort, int, float, double, ...)");
    layout.type = *type;
    std::int64_t dimension = 0;
    if (!parseInteger(trim(fields.required("dimension")), dimension) || dimension != 3)
        fields.fail("dimension", "3 (eikon reads volumes of one scalar per sample)");
    if (const std::string* space = fields.find("space dimension"))
        if (trim(*space) != "3") fields.fail("space dimension", "3");
    layout.dims = readSizes(fields);
    layout.encoding = readEncoding(fields);

    if (const std::string* endian = fields.find("endian")) {
        const std::string e = lower(trim(*endian));
        if (e != "little" && e != "big") fields.fail("endian", "little or big");
        layout.bigEndian = e == "big";
    } else if (scanValueBytes(layout.type) > 1 && layout.encoding != ScanEncoding::Ascii) {
        throw Error(path, "the NRRD header has no \"endian\" field, which " +
                              scanValueTypeName(layout.type) + " samples need");
    }

    if (fields.find("space directions") && fields.find("spacings"))
        throw Error(path, "the NRRD header has both \"space directions\" and \"spacings\"");
    if (fields.find("space directions")) layout.spacing = readSpaceDirections(fields, path);
    if (fields.find("spacings")) layout.spacing = readSpacings(fields);
    if (fields.find("space origin")) layout.origin = readSpaceOrigin(fields);

    layout.byteSkip = readSkip(fields, "byte skip", -1);
    if (layout.byteSkip == -1 && layout.encoding != ScanEncoding::Raw)
        fields.fail("byte skip", "an integer >= 0 (−1 is for raw samples only)");
    const std::int64_t lineSkip = readSkip(fields, "line skip", 0);

    // NRRD spells it "data file" or "datafile"; messages name the spelling the header used.
    const std::string dataKey = fields.find("data file") ? "data file" : "datafile";
    const std::string* dataFile = fields.find(dataKey);
    if (dataFile) {
        const std::string name = trim(*dataFile);
        // The name becomes the `where` of later messages: no control characters in it.
        if (name.empty() || hasControlCharacter(name)) fields.fail(dataKey, "a file name");
        if (name.rfind("LIST", 0) == 0 || name.find('%') != std::string::npos)
            fields.fail(dataKey, "one file (lists and numbered files are not read)");
        const fs::path p(name);
        layout.dataFile = p.is_absolute() ? name : (fs::path(path).parent_path() / p).string();
        if (!fs::is_regular_file(layout.dataFile, ec))
            throw Error(path, "its data file " + printable(layout.dataFile) + " does not exist");
        layout.dataOffset = 0;
    } else {
        if (!attachedData)
            throw Error(path,
                        "the header ends without a blank line before the samples and names "
                        "no \"data file\"");
        layout.dataFile = path;
        layout.dataOffset = std::int64_t(headerBytes);
    }
    layout.dataOffset = skipLines(layout.dataFile, layout.dataOffset, lineSkip);
    return layout;
}

ScanLayout rawScanLayout(const std::string& path, std::optional<glm::ivec3> dims,
                         std::optional<ScanValueType> type, bool bigEndian) {
    ScanLayout layout;
    layout.header = path;
    layout.dataFile = path;
    layout.bigEndian = bigEndian;
    if (!dims || !type) {
        // name_XxYxZ_type.raw, as the SciVis collection names its files
        static const std::regex pattern(R"(_(\d{1,5})x(\d{1,5})x(\d{1,5})_([A-Za-z0-9]+)\.raw$)");
        std::smatch m;
        const std::string name = fs::path(path).filename().string();
        if (!std::regex_search(name, m, pattern))
            throw Error(path, std::string("a raw file needs its ") +
                                  (!dims ? "dimensions" : "value type") +
                                  ": give them (\"dims\" and \"value_type\" in a scene, --dims and "
                                  "--type to eikon convert) or name the file "
                                  "<name>_<X>x<Y>x<Z>_<type>.raw");
        if (!dims) dims = glm::ivec3(std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]));
        if (!type) {
            type = parseScanValueType(m[4]);
            if (!type)
                throw Error(path, "unknown value type \"" + printable(m[4].str()) +
                                      "\" in the file name (uint8, int16, uint16, float32, ...)");
        }
    }
    for (int a = 0; a < 3; ++a)
        if ((*dims)[a] < 1 || (*dims)[a] > kMaxScanSamplesAcross)
            throw Error(path, "dimensions must be in [1, " + std::to_string(kMaxScanSamplesAcross) +
                                  "], got " + std::to_string((*dims)[a]));
    layout.dims = *dims;
    layout.type = *type;
    return layout;
}

}  // namespace eikon
