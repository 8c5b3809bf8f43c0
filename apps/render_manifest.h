#pragma once
// The record of what `eikon render --manifest FILE` wrote: which render (the eikon binary's
// SHA-256, the input's, the settings that change pictures, the frames asked for) and, per frame,
// each file's name and SHA-256. It serves two ends:
// - a farm's output checked against a local run: the tasks' manifests merged (frame lines sorted)
//   equal, byte for byte, the manifest of the same render in one process
//   (scripts/slurm/merge-manifests.sh), since nothing in it names a machine, a path or a chunk;
// - `--resume`: a frame is kept only when every file of it is at its final name with the bytes
//   recorded for this same render; anything else there (a file from another render, one changed
//   or cut short since) is rendered again, with a warning naming it.
// The manifest is rewritten atomically after each frame, so a killed task leaves it naming only
// frames whose files were complete.
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace eikon::app {

struct RenderIdentity {
    std::string build;     // SHA-256 of the eikon binary
    std::string input;     // SHA-256 of the scene or VDB file; a pattern's text
    std::string settings;  // the options that change pictures, in a fixed order
    std::string frames;    // the frames of the whole render (all chunks)
};

class RenderManifest {
public:
    // Reads `path` when it exists: its frames count only when it is of the same render; otherwise
    // `previousIgnored()` says why. Throws eikon::Error(path, ...) for a file that is not a
    // manifest (nothing is overwritten then).
    RenderManifest(std::string path, RenderIdentity identity);

    // Why a manifest found at the path was not trusted ("" when there was none or it matched).
    const std::string& previousIgnored() const { return ignored_; }

    // "" when frame `frame`'s `files` are all recorded for this render with the bytes they have
    // now; otherwise the first one that is not, and why ("<file>: ...").
    std::string whyNotKept(int frame, const std::vector<std::string>& files) const;

    // Records the files just written for `frame` and rewrites the manifest.
    void record(int frame, const std::vector<std::string>& files);
    // Writes the manifest as it is (a chunk with no frames still leaves its header).
    void save() const;

private:
    std::string path_;
    RenderIdentity identity_;
    std::string ignored_;
    // frame -> (file name, SHA-256) in the order written
    std::map<int, std::vector<std::pair<std::string, std::string>>> frames_;
};

}  // namespace eikon::app
