#pragma once
// The progressive viewer's preview scale from a frame budget (eikon view --frame-budget): a
// change is rendered at 1/scale of the window's size in each direction, and the scale is chosen
// so that the next change's picture takes about the budget. A frame's time is modelled as a
// part that does not depend on the picture's size (the simulation step, resampling, ∇n, the
// octree, the light transport: none of them depend on the image) plus the viewing pass, whose
// cost goes with the pixel count, (scale_now / scale)² of the last one's.
namespace eikon {

// Scales a preview may have: powers of two from 1 (full size) to this.
constexpr int kMaxPreviewScale = 16;

// The scale for the next change's picture, given the last change's: rendered at 1/`scale`, it
// took `frameMs`, of which `viewMs` was the viewing pass. The finest scale whose predicted time
// fits the budget; a finer scale than now only when it fits in kPreviewFinerMargin of it, so
// that frame-to-frame noise does not flip the scale back and forth. None fits: the coarsest.
// A budget ≤ 0, or times that are not finite: `scale` unchanged.
constexpr double kPreviewFinerMargin = 0.8;
int budgetedPreviewScale(int scale, double frameMs, double viewMs, double budgetMs);

}  // namespace eikon
