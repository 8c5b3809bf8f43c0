#pragma once
// The grammar of `--frames`: which frames a command renders or writes.
//   7          one frame
//   1-10       first to last, inclusive
//   1-10x2     first to last in steps (1, 3, 5, 7, 9)
//   1,3,5-7    a comma list of the above
// Frames are whole numbers from 0 to 2^31 − 1 (as a scene's frame_end); no spaces, signs or other
// separators. The frames come out ascending, each once, at most kMaxListedFrames of them.
#include <string>
#include <vector>

namespace eikon {

constexpr int kMaxListedFrames = 1000000;

// Throws eikon::Error at "--frames" with the grammar in its reason for anything else.
std::vector<int> parseFrameList(const std::string& text);

// True when `frames` (ascending, each once) is one run first..last with no gap.
bool isContiguous(const std::vector<int>& frames);

// The file of frame `frame` in a per-frame sequence, as `eikon simulate` writes its caches and
// `eikon render` its images: <directory>/<name>_<frame, at least 4 digits>.<ext>
std::string framePath(const std::string& directory, const std::string& name, int frame,
                      const char* ext);

}  // namespace eikon
