#include "core/atomic_write.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace eikon {

void syncFileToDisk(const std::string& file, const std::string& nameForErrors) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        throw Error(nameForErrors,
                    std::string("could not reopen to sync: ") + std::strerror(errno));
    const int synced = ::fsync(fd);
    const int syncError = errno;
    const int closed = ::close(fd);
    if (synced != 0)
        throw Error(nameForErrors, std::string("could not write: ") + std::strerror(syncError));
    if (closed != 0)
        throw Error(nameForErrors, std::string("could not write: ") + std::strerror(errno));
}

void syncFolderToDisk(const std::filesystem::path& folder) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

bool removeStalePartial(const std::string& path) {
    std::error_code ec;
    return std::filesystem::remove(path + ".partial", ec);
}

}  // namespace eikon
