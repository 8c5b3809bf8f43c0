#pragma once
// Writing a file so that a failure never destroys what was there: `write` fills "<path>.partial",
// which replaces `path` only after it succeeded. Any failure is an eikon::Error naming `path`.
#include <filesystem>
#include <string>

#include "core/error.h"

namespace eikon {

template <typename WriteFn>
void writeAtomically(const std::string& path, WriteFn write) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::error_code ec;
    if (!target.parent_path().empty() && !fs::is_directory(target.parent_path(), ec))
        throw Error(path, "folder '" + target.parent_path().string() + "' does not exist");
    const std::string partial = path + ".partial";
    try {
        write(partial);
    } catch (const Error&) {
        fs::remove(partial, ec);
        throw;
    } catch (const std::exception& e) {
        fs::remove(partial, ec);
        throw Error(path, std::string("could not write: ") + e.what());
    }
    fs::rename(partial, target, ec);
    if (ec) {
        fs::remove(partial, ec);
        throw Error(path, "could not replace the file: " + ec.message());
    }
}

}  // namespace eikon
