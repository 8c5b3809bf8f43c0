#pragma once
// The interleaved view's window of slices, the same on the CPU twin and the GPU
// (plane_sweep_view_cpu.cpp, plane_sweep_view_gpu.cpp): how many slices of the fluence and
// mean-direction volumes are held, and after which slices the view rays advance.

namespace eikon {

// Every kInterleavedWindowSlices − 1 slices the view rays advance (the ray states are read and
// written once for that many planes); a ray may turn back kInterleavedWindowSlices − 2 slices
// before it reads one dropped.
constexpr int kInterleavedWindowSlices = 8;

// Whether the view rays advance after the swept-th slice of `depth`: every
// kInterleavedWindowSlices − 1 slices from the first, and after the last. A sample not ready at
// one turn needs a slice swept after it, so at the next its slices are among those held.
inline bool interleavedViewTurn(int swept, int depth) {
    return (swept - 1) % (kInterleavedWindowSlices - 1) == 0 || swept == depth;
}

}  // namespace eikon
