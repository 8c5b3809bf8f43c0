#pragma once
// OpenMesh's readers talk through global streams (omerr, omlog, omout) that go to stderr and
// stdout. While one of these is alive, they write into a buffer instead, so that a library call
// prints nothing of its own and what OpenMesh said can become part of an eikon::Error or a note.
// The streams' buffers are swapped, not their targets: OpenMesh's disconnect() leaks the target
// it removes, which LeakSanitizer reports.
// Not thread-safe (the streams are process-wide); meshes are loaded from one thread.
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace eikon {

class OpenMeshMessages {
public:
    OpenMeshMessages();
    ~OpenMeshMessages();
    OpenMeshMessages(const OpenMeshMessages&) = delete;
    OpenMeshMessages& operator=(const OpenMeshMessages&) = delete;

    // The distinct non-empty lines said so far, trimmed, in the order first said.
    std::vector<std::string> lines() const;

private:
    std::stringbuf buffer_;
    std::streambuf* savedErr_;
    std::streambuf* savedLog_;
    std::streambuf* savedOut_;
};

}  // namespace eikon
