#pragma once
// The face lines of an OBJ file, checked before OpenMesh reads them.
//
// OpenMesh 9.0's OBJ reader (OBJReader.cc) parses each corner of an `f` line as v, v/vt, v//vn
// or v/vt/vn, and asserts that a vertex index came before a texture index: Debian's build keeps
// the assertion, so "f /0" aborted `eikon info` (SIGABRT, found by fuzz_obj). A corner it cannot
// parse is skipped without a word, or read as index 0 (the vertex before the first), so a typo
// silently changed the face.
#include <string>

namespace eikon {

// Throws eikon::Error naming the file and line when a corner of a face line is not v, v/vt,
// v//vn or v/vt/vn with whole-number indices (negative ones count back from the last vertex, as
// OBJ allows; at most nine digits).
void checkObjFaceLines(const std::string& path, const std::string& bytes);

}  // namespace eikon
