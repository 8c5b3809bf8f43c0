#pragma once
// Frame-number tokens in file names, as the tools users come from write them:
//   Blender  fluid_data_####.vdb   (the run's width is the zero padding)
//   printf   fluid_data_%04d.vdb   (%d unpadded)
//   Houdini  fluid_data_$F4.vdb    ($F unpadded)
// Eikon keeps one form, the run of '#', and reads the others into it, so a sequence or an output
// pattern means the same whichever spelling the user pasted.
#include <string>

namespace eikon {

// `name` with its frame token as a run of '#' of the token's width ("%04d" and "$F4" -> "####",
// "%d" and "$F" -> "#"); unchanged when it has none. Throws eikon::Error at `where` when it has
// more than one token (one name cannot hold two frame numbers) or a printf token other than %d
// and %0Nd.
std::string toHashPattern(const std::string& name, const std::string& where);

// True when `name` holds a run of '#'.
bool hasHashRun(const std::string& name);

// The pattern's '#' run replaced by `frame`, zero padded to the run's width (a wider number is
// written whole, as Blender does); the pattern itself when it has no run.
std::string expandHashPattern(const std::string& pattern, int frame);

}  // namespace eikon
