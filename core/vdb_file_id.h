#pragma once
// OpenVDB stamps every file it writes with a random UUID (io::Archive's header), so the same grids
// written twice give different bytes. Eikon promises byte-identical output for the same inputs
// (deterministic regression tests compare files), so after writing, the UUID is replaced by one
// derived from the rest of the file's bytes: identical files get identical identifiers, and
// different contents still get different ones, which is all OpenVDB uses it for (recognising
// the same file when it reopens one).
#include <string>

namespace eikon {

// Rewrites, in place, the UUID of the VDB file at `path` as a hash of every other byte. Throws
// eikon::Error naming the file when it cannot be read or written, or when its header is not the
// layout OpenVDB 6-11 writes (magic, file version ≥ 222, library version, a flag, 36 UUID
// characters), rather than corrupting an unknown format.
void makeVdbFileIdDeterministic(const std::string& path);

}  // namespace eikon
