#include "sim/mesh_info.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

namespace eikon {

namespace {

std::string triple(const glm::vec3& v) {
    std::ostringstream s;
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string formatMeshInfo(const std::string& path, const LoadedMesh& loaded, const MeshReport& r) {
    std::string format = std::filesystem::path(path).extension().string().substr(1);
    std::transform(format.begin(), format.end(), format.begin(),
                   [](unsigned char c) { return char(std::toupper(c)); });
    std::ostringstream s;
    s << path << ": " << format << " mesh, " << plural(r.vertices, "vertex", "vertices");
    if (r.unreferencedVertices > 0) s << " (" << r.unreferencedVertices << " unreferenced)";
    s << ", " << plural(r.faces, "face", "faces") << " ("
      << plural(r.triangles, "triangle", "triangles") << ")\n";
    s << "  bounds " << triple(r.bounds.min) << " -> " << triple(r.bounds.max) << ", size "
      << triple(r.bounds.size()) << "\n";
    s << "  " << plural(r.edges, "edge", "edges") << ", "
      << plural(r.components, "component", "components") << ", Euler characteristic "
      << r.eulerCharacteristic << "\n";
    s << "  watertight: " << (r.watertight() ? "yes" : "no");
    if (!r.holeSizes.empty()) {
        s << "; holes of";
        for (std::size_t i = 0; i < r.holeSizes.size(); ++i)
            s << (i == 0 ? " " : ", ") << r.holeSizes[i];
        s << " edges";
    }
    s << "\n";
    s << "  signed volume " << r.signedVolume
      << (r.watertight() ? "" : " (meaningless: the mesh is open or non-manifold)") << "\n";
    const std::vector<std::string> problems = meshProblems(r);
    if (problems.empty()) {
        s << "  problems: none\n";
    } else {
        s << "  problems:\n";
        for (const std::string& problem : problems) s << "    " << problem << "\n";
        const std::string hint = closeHolesHint(r);
        if (!hint.empty()) s << "  to close holes: " << hint << "\n";
    }
    if (!loaded.notes.empty()) {
        s << "  reader notes:\n";
        for (const std::string& note : loaded.notes) s << "    " << note << "\n";
    }
    return s.str();
}

}  // namespace eikon
