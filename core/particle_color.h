#pragma once
// Particle colour (Magnus's thesis, ch. 4: the colour of the light a medium's particles scatter
// and emit, kept apart from the medium colour its absorption gives): a material's scattering and
// emission toward the viewer are tinted, per channel, by color(f), f its field's own value
// (post-classified: interpolated first, then mapped, so a colour band narrower than the field's
// change between voxels is not blended away), averaged over each view step from the values at its
// ends (pre-integrated, so a band thinner than a step counts by its width). Extinction is not
// tinted: a material's opacity and medium colour stay its absorption and scattering coefficients
// (times its transfer function's amount, core/transfer_function.h). The colour is a map by name
// (matplotlib's viridis, inferno, ...) over a range of values, or piecewise linear through
// (value, r, g, b) points; the GPU and the CPU twin read it from one table of
// EK_PARTICLE_COLOR_TABLE entries (shaders/shared/optics.h particleColorOverStep).
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/scene.h"

namespace eikon {

// At most this many (value, r, g, b) points a particle colour.
constexpr std::size_t kMaxParticleColorPoints = 16;

// The colour maps "particle_color" knows by name, in the order the docs list them.
const std::vector<std::string>& colorMapNames();

// What is wrong with `spec`, "" when nothing is: an unknown map ("unknown colour map 'x'; known:
// viridis, ..."), a range whose high end is not above its low end or not finite, fewer than 2 or
// more than kMaxParticleColorPoints points, values not finite or not strictly increasing, a
// colour channel negative or not finite. The scene's "particle_color" and the library's share it.
std::string particleColorProblem(const ParticleColorSpec& spec);

// The values the first and last entries of its table stand for: the map's range, or the first
// and last points' values.
glm::vec2 particleColorRange(const ParticleColorSpec& spec);

// The linear colour at `value`: a map's entries (converted from sRGB) interpolated linearly, or
// the points' colours linearly between neighbouring points; flat beyond either end. NaN: the
// first colour.
glm::vec3 particleColorAt(const ParticleColorSpec& spec, float value);

// `entries` colours evenly spaced over particleColorRange (a map's own entries, exactly, when
// `entries` is its size, 256): the table shaders/shared/optics.h interpolates.
std::vector<glm::vec3> particleColorTable(const ParticleColorSpec& spec, int entries);

// The sRGB transfer curve's inverse: a display value in [0, 1] to linear.
float srgbToLinear(float display);

}  // namespace eikon
