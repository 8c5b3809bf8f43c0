#include "sim/openmesh_messages.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>

namespace eikon {

OpenMeshMessages::OpenMeshMessages()
    : savedErr_(omerr().rdbuf(&buffer_)),
      savedLog_(omlog().rdbuf(&buffer_)),
      savedOut_(omout().rdbuf(&buffer_)) {}

OpenMeshMessages::~OpenMeshMessages() {
    omerr().rdbuf(savedErr_);
    omlog().rdbuf(savedLog_);
    omout().rdbuf(savedOut_);
}

std::vector<std::string> OpenMeshMessages::lines() const {
    std::vector<std::string> out;
    std::istringstream in(buffer_.str());
    for (std::string line; std::getline(in, line);) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos) continue;
        line = line.substr(first, line.find_last_not_of(" \t\r") + 1 - first);
        if (std::find(out.begin(), out.end(), line) == out.end()) out.push_back(line);
    }
    return out;
}

}  // namespace eikon
