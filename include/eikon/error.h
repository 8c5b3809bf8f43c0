#pragma once
// The one exception type that reaches users (of the command line and of the library, which
// throws it from every call of include/eikon/eikon.h). Its message always reads "<where>:
// <reason>", where <where> is a file path, a JSON path inside a scene file, or a pipeline stage, so
// that a one-line report tells the user what to fix.
#include <stdexcept>
#include <string>

namespace eikon {

class Error : public std::runtime_error {
public:
    Error(std::string where, std::string reason)
        : std::runtime_error(where + ": " + reason),
          where_(std::move(where)),
          reason_(std::move(reason)) {}

    const std::string& where() const { return where_; }
    const std::string& reason() const { return reason_; }

private:
    std::string where_;
    std::string reason_;
};

}  // namespace eikon
