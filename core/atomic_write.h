#pragma once
// Writing a file so that a failure never destroys what was there: `write` fills "<path>.partial",
// which is flushed to the disk (fsync) and only then renamed over `path`, and the folder is synced
// so that the rename itself survives a crash. Any failure (a full disk, a file-size limit, a
// failed close) is an eikon::Error naming `path` and the system's reason, and leaves `path` as it
// was: the old complete file, or none. A stale "<path>.partial" left by a killed run is ours to
// remove (removeStalePartial).
#include <filesystem>
#include <string>

#include "core/error.h"

namespace eikon {

// Flushes `file`'s data to the disk; throws eikon::Error naming `nameForErrors` when the system
// reports that it could not (ENOSPC surfaces here on file systems that allocate late).
void syncFileToDisk(const std::string& file, const std::string& nameForErrors);
// Makes a rename in `folder` durable; a folder that cannot be synced (some network file systems)
// is not an error: the file itself is complete either way.
void syncFolderToDisk(const std::filesystem::path& folder);
// Removes "<path>.partial" if a killed run left it; returns whether there was one.
bool removeStalePartial(const std::string& path);

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
        syncFileToDisk(partial, path);
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
    syncFolderToDisk(target.parent_path().empty() ? fs::path(".") : target.parent_path());
}

}  // namespace eikon
