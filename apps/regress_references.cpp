#include "apps/regress_references.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/printable.h"
#include "core/sha256.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

bool isHexDigest(const std::string& s) {
    if (s.size() != 64) return false;
    for (char c : s)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    return true;
}

}  // namespace

ReferenceManifest::ReferenceManifest(const std::string& suiteDir)
    : folder_((fs::path(suiteDir) / "references").string()) {
    std::ifstream in(manifestPath(), std::ios::binary);
    if (!in) return;  // no references yet
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty()) continue;
        const std::string where = manifestPath() + ":" + std::to_string(number);
        const std::string hash = line.substr(0, 64);
        if (line.size() < 67 || !isHexDigest(hash) || line.compare(64, 2, "  ") != 0)
            throw Error(where, "expected '<64 lowercase hex digits>  <path>', got '" +
                                   printable(line.substr(0, 100)) +
                                   "'; restore the file or rerun with --update");
        const std::string key = line.substr(66);
        if (key.find("..") != std::string::npos || key.front() == '/')
            throw Error(where, "path '" + printable(key) + "' leaves the references folder");
        entries_[key] = hash;
    }
}

std::optional<std::string> ReferenceManifest::hashOf(const std::string& key) const {
    const auto it = entries_.find(key);
    if (it == entries_.end()) return std::nullopt;
    return it->second;
}

std::vector<std::string> ReferenceManifest::keysOfCase(const std::string& caseName) const {
    std::vector<std::string> keys;
    const std::string prefix = caseName + "/";
    for (auto it = entries_.lower_bound(prefix);
         it != entries_.end() && it->first.compare(0, prefix.size(), prefix) == 0; ++it)
        keys.push_back(it->first);
    return keys;
}

void ReferenceManifest::replaceCase(const std::string& caseName,
                                    const std::map<std::string, std::string>& files) {
    for (const std::string& key : keysOfCase(caseName)) entries_.erase(key);
    for (const auto& [key, hash] : files) entries_[key] = hash;
}

void ReferenceManifest::save() const {
    std::ostringstream text;
    for (const auto& [key, hash] : entries_) text << hash << "  " << key << "\n";
    std::error_code ec;
    fs::create_directories(folder_, ec);
    if (ec) throw Error(folder_, "cannot create the references folder: " + ec.message());
    writeAtomically(manifestPath(), [&](const std::string& partial) {
        std::ofstream out(partial, std::ios::binary);
        out << text.str();
        out.close();
        if (!out) throw Error(manifestPath(), "could not write the manifest");
    });
}

std::map<std::string, std::string> installReferences(
    const std::string& referenceFolder, const std::string& caseName,
    const std::map<std::string, std::string>& files, const std::set<std::string>& hashOnly) {
    const fs::path target = fs::path(referenceFolder) / caseName;
    const fs::path fresh = fs::path(referenceFolder) / ("." + caseName + ".new");
    const fs::path old = fs::path(referenceFolder) / ("." + caseName + ".old");
    std::error_code ec;
    fs::remove_all(fresh, ec);
    std::map<std::string, std::string> hashes;
    try {
        fs::create_directories(fresh);
        for (const auto& [key, source] : files) {
            if (hashOnly.count(key)) {
                hashes[key] = sha256OfFile(source);
                continue;
            }
            const fs::path destination = fresh / key.substr(caseName.size() + 1);
            fs::create_directories(destination.parent_path());
            fs::copy_file(source, destination, fs::copy_options::overwrite_existing);
            hashes[key] = sha256OfFile(destination.string());
        }
        fs::remove_all(old, ec);
        if (fs::exists(target)) fs::rename(target, old);
        fs::rename(fresh, target);
        fs::remove_all(old, ec);
    } catch (const fs::filesystem_error& e) {
        fs::remove_all(fresh, ec);
        if (!fs::exists(target, ec) && fs::exists(old, ec)) fs::rename(old, target, ec);
        throw Error(target.string(), std::string("cannot write the references: ") + e.what());
    }
    return hashes;
}

}  // namespace eikon::app
