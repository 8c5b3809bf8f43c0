#pragma once
// Where tests find the shared real-world data and where they may write. ctest runs test cases as
// separate processes in parallel, so each case asks for its own scratch folder by name.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace eikon::test {

// The folder the build was configured with, unless the environment names another: a test
// binary carried to another machine (scripts/gpu-check.sh --bundle) finds the sources, the
// shared data and its scratch space where they are there.
inline std::string folderOf(const char* variable, const char* built) {
    const char* env = std::getenv(variable);
    return env && *env ? std::string(env) : std::string(built);
}

inline std::string sharedData(const std::string& relative) {
    return folderOf("EIKON_TEST_SHARED_DATA", EIKON_SHARED_DATA) + "/" + relative;
}

inline std::string sourcePath(const std::string& relative) {
    return folderOf("EIKON_TEST_SOURCE_DIR", EIKON_SOURCE_DIR) + "/" + relative;
}

// A fresh, empty folder for one test case.
inline std::string scratchDir(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(folderOf("EIKON_TEST_SCRATCH_DIR", EIKON_TEST_SCRATCH)) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

}  // namespace eikon::test
