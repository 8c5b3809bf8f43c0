#include "apps/render_manifest.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/sha256.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

const char* const kFirstLine = "# eikon render manifest: the render, then each frame's files";
constexpr std::size_t kMaxManifestBytes = 64u << 20;  // a million frames' lines fit

std::vector<std::string> fieldsOf(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string f; std::getline(in, f, '\t');) out.push_back(f);
    return out;
}

std::string nameOf(const std::string& path) {
    return fs::path(path).filename().string();
}

}  // namespace

RenderManifest::RenderManifest(std::string path, RenderIdentity identity)
    : path_(std::move(path)), identity_(std::move(identity)) {
    std::error_code ec;
    if (!fs::exists(path_, ec)) return;
    if (fs::file_size(path_, ec) > kMaxManifestBytes)
        throw Error(path_, "larger than a manifest can be; not overwritten");
    std::ifstream in(path_);
    std::string line;
    if (!std::getline(in, line) || line != kFirstLine)
        throw Error(path_,
                    "not an eikon render manifest (its first line differs); not "
                    "overwritten: give --manifest another file");
    std::map<std::string, std::string> header;
    while (std::getline(in, line)) {
        const std::vector<std::string> f = fieldsOf(line);
        if (f.size() == 2) header[f[0]] = f[1];
        if (f.size() == 3 && f[0] == "frame") break;  // the column names
    }
    const std::pair<const char*, const std::string*> mine[] = {{"build", &identity_.build},
                                                               {"input", &identity_.input},
                                                               {"settings", &identity_.settings},
                                                               {"frames", &identity_.frames}};
    for (const auto& [key, value] : mine)
        if (header[key] != *value) {
            ignored_ = path_ + ": from another render (its " + key +
                       " line differs): its frames are not kept";
            return;
        }
    while (std::getline(in, line)) {
        const std::vector<std::string> f = fieldsOf(line);
        if (f.size() != 3 || f[0].empty() ||
            f[0].find_first_not_of("0123456789") != std::string::npos || f[0].size() > 10 ||
            f[2].size() != 64)
            continue;  // not a frame line: nothing is kept on its word
        frames_[std::stoi(f[0])].emplace_back(f[1], f[2]);
    }
}

std::string RenderManifest::whyNotKept(int frame, const std::vector<std::string>& files) const {
    const auto recorded = frames_.find(frame);
    for (const std::string& file : files) {
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) return file + ": not there";
        const std::string* hash = nullptr;
        if (recorded != frames_.end())
            for (const auto& [name, sha] : recorded->second)
                if (name == nameOf(file)) hash = &sha;
        if (!hash) return file + ": not recorded as this render's (a file from another render?)";
        if (sha256OfFile(file) != *hash)
            return file + ": its bytes differ from those recorded (cut short or overwritten)";
    }
    return "";
}

void RenderManifest::record(int frame, const std::vector<std::string>& files) {
    auto& entries = frames_[frame];
    entries.clear();
    for (const std::string& file : files) entries.emplace_back(nameOf(file), sha256OfFile(file));
    save();
}

void RenderManifest::save() const {
    std::ostringstream text;
    text << kFirstLine << "\n"
         << "build\t" << identity_.build << "\n"
         << "input\t" << identity_.input << "\n"
         << "settings\t" << identity_.settings << "\n"
         << "frames\t" << identity_.frames << "\n"
         << "frame\tfile\tsha256\n";
    for (const auto& [frame, entries] : frames_)
        for (const auto& [name, sha] : entries)
            text << frame << "\t" << name << "\t" << sha << "\n";
    const fs::path parent = fs::path(path_).parent_path();
    std::error_code ec;
    if (!parent.empty()) fs::create_directories(parent, ec);
    writeAtomically(path_, [&](const std::string& partial) {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        out << text.str();
        out.close();
        if (!out) throw Error(path_, "could not write the manifest");
    });
}

}  // namespace eikon::app
