#include "sim/openmesh_messages.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <iostream>

namespace eikon {

OpenMeshMessages::OpenMeshMessages() {
    hadCerr_ = omerr().disconnect(std::cerr);
    hadClog_ = omlog().disconnect(std::clog);
    hadCout_ = omout().disconnect(std::cout);
    omerr().connect(buffer_);
    omlog().connect(buffer_);
    omout().connect(buffer_);
}

OpenMeshMessages::~OpenMeshMessages() {
    omerr().flush();
    omlog().flush();
    omout().flush();
    omerr().disconnect(buffer_);
    omlog().disconnect(buffer_);
    omout().disconnect(buffer_);
    if (hadCerr_) omerr().connect(std::cerr);
    if (hadClog_) omlog().connect(std::clog);
    if (hadCout_) omout().connect(std::cout);
}

std::vector<std::string> OpenMeshMessages::lines() const {
    omerr().flush();
    omlog().flush();
    omout().flush();
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
