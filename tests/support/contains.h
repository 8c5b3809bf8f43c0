#pragma once
// The one substring check the tests share (messages, command output).
#include <string>

namespace eikon::test {

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace eikon::test
