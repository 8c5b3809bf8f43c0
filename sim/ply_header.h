#pragma once
// The header of a PLY file, read by a strict grammar of our own before OpenMesh sees the file.
//
// OpenMesh 9.0's header parser trusts what it reads (measured, issue 14): a `property` line before
// any `element` dereferences an empty element list (SEGV); a missing or unreadable format version
// (`format ascii`, `-inf`, `abc`, `1e308`), a garbled keyword or an `end_header` that is not a word
// of its own sends it into an endless loop that allocates without bound. So the header is parsed
// here, line by line:
//     ply
//     format ascii|binary_little_endian|binary_big_endian 1.0
//     comment ... | obj_info ...                       (anywhere, any text)
//     element NAME COUNT                               (COUNT: decimal, below 2^32)
//     property TYPE NAME                               (after an element)
//     property list COUNT_TYPE ITEM_TYPE NAME          (COUNT_TYPE integral)
//     end_header                                       (a line of its own)
// TYPE is one of char uchar short ushort int uint float double int8 uint8 int16 uint16 int32
// uint32 float32 float64. Blank lines are skipped. Lines end in \n or \r\n.
// OpenMesh is then handed canonicalPlyHeader() in front of the body, never the file's own header,
// so that it parses only text this grammar produced.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace eikon {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyProperty {
    std::string name;
    std::string typeName;  // as written ("uchar", "float32"): OpenMesh tells some synonyms apart
    PlyType type = PlyType::Float32;  // the items' type, for a list
    bool isList = false;
    std::string countTypeName;  // lists only
    PlyType countType = PlyType::UInt8;
    std::size_t line = 0;  // of its `property` line, for messages
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    std::size_t line = 0;  // of its `element` line, for messages
};

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    std::size_t bodyOffset = 0;  // first byte after the `end_header` line
    std::size_t bodyLine = 0;    // the line number the body starts on (ASCII messages)
};

// Bytes of one value of `type` in a binary body.
std::size_t plyTypeSize(PlyType type);
bool plyTypeIsIntegral(PlyType type);

// Parses the header of `bytes` (the whole file). Throws eikon::Error at "<path>:<line>" naming
// what is wrong (the offending text escaped by printable()).
PlyHeader parsePlyHeader(const std::string& path, const std::string& bytes);

// The header written back in the grammar's own form (no comments, one space between words, \n
// line ends), to put in front of the body for OpenMesh.
std::string canonicalPlyHeader(const PlyHeader& header);

}  // namespace eikon
