#pragma once
// OpenMesh's readers talk through global streams (omerr, omlog, omout) that go to stderr and
// stdout. While one of these is alive, they go to a buffer instead, so that a library call prints
// nothing of its own and what OpenMesh said can become part of an eikon::Error or a note.
// Not thread-safe (the streams are process-wide); meshes are loaded from one thread.
#include <sstream>
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
    std::ostringstream buffer_;
    bool hadCerr_ = false, hadClog_ = false, hadCout_ = false;
};

}  // namespace eikon
