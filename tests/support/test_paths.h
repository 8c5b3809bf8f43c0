#pragma once
// Where tests find the shared real-world data and where they may write. ctest runs test cases as
// separate processes in parallel, so each case asks for its own scratch folder by name.
#include <filesystem>
#include <string>

namespace eikon::test {

inline std::string sharedData(const std::string& relative) {
    return std::string(EIKON_SHARED_DATA) + "/" + relative;
}

inline std::string sourcePath(const std::string& relative) {
    return std::string(EIKON_SOURCE_DIR) + "/" + relative;
}

// A fresh, empty folder for one test case.
inline std::string scratchDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(EIKON_TEST_SCRATCH) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

}  // namespace eikon::test
