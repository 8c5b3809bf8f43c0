#include "apps/output_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.h"
#include "core/frame_pattern.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// A folder's files: the scene's name, numbered when the render is more than a single frame.
std::string folderName(const std::string& name, bool numbered) {
    const std::string pattern = toHashPattern(name, "output name '" + name + "'");
    if (hasHashRun(pattern) || !numbered) return pattern;
    return pattern + "_####";
}

// Images eikon does not write: refused, so that -o still.jpg is not taken for a folder.
bool isOtherImageExtension(const std::string& ext) {
    for (const char* other : {".jpg", ".jpeg", ".tif", ".tiff", ".bmp", ".tga", ".hdr", ".webp",
                              ".gif", ".ppm", ".pfm", ".dpx", ".cin", ".rgb", ".sgi", ".jp2"})
        if (ext == other) return true;
    return false;
}

}  // namespace

std::string OutputFiles::path(int frame, const char* ext) const {
    return (fs::path(directory) / (expandHashPattern(nameTemplate, frame) + "." + ext)).string();
}

std::vector<std::string> OutputFiles::paths(const std::vector<int>& frames) const {
    std::vector<std::string> out;
    for (int frame : frames) {
        if (png) out.push_back(path(frame, "png"));
        if (exr) out.push_back(path(frame, "exr"));
    }
    return out;
}

OutputFiles resolveOutputFiles(const std::string& dashO, const OutputSettings& output,
                               const std::vector<int>& frames, bool inputHasOneFrame) {
    OutputFiles files;
    files.png = output.png;
    files.exr = output.exr;
    const bool numbered = frames.size() > 1 || !inputHasOneFrame;
    std::error_code ec;
    const std::string ext = lowercase(fs::path(dashO).extension().string());
    // Anything else that is not an image's extension is a folder's name ("renders/v1.2").
    const bool image = ext == ".png" || ext == ".exr" || isOtherImageExtension(ext);
    const bool folder =
        dashO.empty() || dashO.back() == '/' || fs::is_directory(dashO, ec) || !image;
    if (folder) {
        if (!dashO.empty() && hasHashRun(toHashPattern(dashO, "-o")))
            throw Error("-o", "'" + dashO +
                                  "' has a frame pattern but no image extension; write "
                                  "shot_####.png or shot_####.exr");
        files.directory = dashO.empty() ? output.directory : dashO;
        files.nameTemplate = folderName(output.name, numbered);
        return files;
    }
    const fs::path given(dashO);
    if (ext != ".png" && ext != ".exr")
        throw Error("-o", "'" + dashO +
                              "': eikon writes .png and .exr images; name a file ending in one "
                              "of them, a pattern such as shot_####.png, or a folder ending in /");
    files.directory = given.parent_path().empty() ? "." : given.parent_path().string();
    files.nameTemplate = toHashPattern(given.stem().string(), "-o");
    // The extension picks the format; --exr (or the scene's exr) adds an EXR beside a PNG.
    files.png = ext == ".png";
    files.exr = ext == ".exr" || output.exr;
    if (!hasHashRun(files.nameTemplate) && frames.size() > 1)
        throw Error("-o", "'" + dashO + "' names one file, but " + std::to_string(frames.size()) +
                              " frames are rendered; write " + files.nameTemplate + "_####" + ext +
                              " for one file per frame, or a folder ending in /");
    return files;
}

}  // namespace eikon::app
