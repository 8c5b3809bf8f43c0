#pragma once
// A suite's references: the files a case's outputs are compared against, under
// SUITE/references/CASE/, and one manifest, SUITE/references/SHA256SUMS, listing each with its
// SHA-256 in sha256sum's format ("<hash>  CASE/cpu/frame_0001.png", sorted), so that
// `sha256sum -c` checks them by hand and a hash comparison needs no second copy. A reference file
// whose bytes do not match the manifest is corrupt (or was edited by hand): reported, not used.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace eikon::app {

class ReferenceManifest {
public:
    // Reads SUITE/references/SHA256SUMS when there is one. Throws eikon::Error("<file>:<line>",
    // reason) on a line that is not "<64 hex digits>  <path>".
    explicit ReferenceManifest(const std::string& suiteDir);

    const std::string& folder() const { return folder_; }  // SUITE/references
    std::string manifestPath() const { return folder_ + "/SHA256SUMS"; }
    // The hash listed for "CASE/relative", if any.
    std::optional<std::string> hashOf(const std::string& key) const;
    // The keys listed under CASE/, sorted.
    std::vector<std::string> keysOfCase(const std::string& caseName) const;
    // Replaces every entry of the case with `files` (key → hash).
    void replaceCase(const std::string& caseName, const std::map<std::string, std::string>& files);
    // Writes the manifest atomically (core/atomic_write.h).
    void save() const;

private:
    std::string folder_;
    std::map<std::string, std::string> entries_;  // key → hash
};

// Copies `files` (key under CASE/ → the new output's path) into SUITE/references/CASE/, replacing
// that folder as a whole: the new files go to a temporary folder first, so a failed copy leaves
// the old references as they were. Keys in `hashOnly` are not copied, only hashed (a cache
// compared by hash needs no second copy, and caches are large). Returns key → SHA-256 for the
// manifest.
std::map<std::string, std::string> installReferences(
    const std::string& referenceFolder, const std::string& caseName,
    const std::map<std::string, std::string>& files, const std::set<std::string>& hashOnly);

}  // namespace eikon::app
