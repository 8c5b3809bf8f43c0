// An installed libeikon.so reads its shaders from <prefix>/share/eikon/shaders, found from where
// the library itself lies (dladdr), so `cmake --install --prefix P` works for any P; the build's
// own shaders folder still comes first while it exists (render/shader_program.h).
#include <dlfcn.h>

#include <filesystem>

#include "api/shader_location.h"
#include "render/shader_program.h"

namespace fs = std::filesystem;

namespace eikon {

void useInstalledShaders() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&useInstalledShaders), &info) == 0 || !info.dli_fname)
        return;
    const fs::path library = fs::absolute(info.dli_fname).parent_path();
    // lib/ or lib/<multiarch>/ below the prefix.
    for (const fs::path& prefix : {library.parent_path(), library.parent_path().parent_path()}) {
        std::error_code ec;
        const fs::path shaders = prefix / "share" / "eikon" / "shaders";
        if (fs::is_directory(shaders, ec)) {
            setShaderDirectoryFallback(shaders.string());
            return;
        }
    }
}

}  // namespace eikon
