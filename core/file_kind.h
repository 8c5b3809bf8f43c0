#pragma once
// What a file is, from its first bytes rather than its name: `eikon render smoke.VDB` or a cache
// named .bin by another tool is still a VDB file, and a scene saved as .txt is still a scene.
#include <string>

namespace eikon {

enum class FileKind {
    Vdb,      // OpenVDB: the int32 magic 0x56444220 first
    NanoVdb,  // NanoVDB: "NanoVDB" first (its grid and file magics)
    Json,     // a scene: '{' first, after white space and a UTF-8 byte-order mark
};

// Throws eikon::Error at `path` when the file is missing, a folder, unreadable, empty, or none
// of the kinds (the reason shows its first bytes, so a PNG or a zip is recognisable).
FileKind sniffFileKind(const std::string& path);

// True when `path` starts with NanoVDB's magic; false for anything else, including a file that
// cannot be read (the reader that follows says why).
bool isNanoVdbFile(const std::string& path);

}  // namespace eikon
