// The wavefront's trace in rounds (docs/methods.md `wavefront`), the same on the GPU
// (render/transport/wavefront/wavefront_tracing_gpu.cpp, shaders/wavefront_trace.comp,
// shaders/wavefront_scan.comp) and in the CPU twin (wavefront_tracing_cpu.cpp).
//
// A pass's patches live in a list, starting patches in index order. Each round every patch of
// the list runs patchRound (shared/wavefront.h): it ends, asks to be split, or goes on after
// EK_WAVE_ROUND_STEPS steps. Between rounds the list is compacted and expanded in list order by
// prefix sums: an ended patch leaves no entry, one going on leaves itself, one whose split is
// granted its four children in child order, where it was. So a starting patch's descendants stay
// together in the list, in the order of their starting patches. Each starting patch may make
// max_patches ÷ (the pass's starting patches) patches, itself included (so a wavefront that
// tears in one place cannot take the budget of the rest): its first requests in list order are
// granted while they fit; those refused go on unsplit for good. The list's order, every patch's
// steps and which splits are refused follow from the inputs alone, never from thread timing, and
// both backends compute the same patches.
// Word offsets, the same for C++ and GLSL.
#ifndef EIKON_SHARED_WAVEFRONT_ROUNDS_H
#define EIKON_SHARED_WAVEFRONT_ROUNDS_H

// Steps a patch takes in one round at most. It bounds a dispatch's length on a GPU (drivers stop
// long ones); the split grants follow the rounds, so the twin uses the same number.
#define EK_WAVE_ROUND_STEPS 256
#define EK_WAVE_GROUP 64        // invocations per work group of the trace and scatter dispatches
#define EK_WAVE_SCAN_GROUP 256  // patches per block of the prefix sums

// The round header (uint words), kept on the GPU.
#define EK_WAVE_NEXT 0      // patches in the list the round writes
#define EK_WAVE_REQUESTS 1  // split requests of the round
#define EK_WAVE_HEADER 4    // words

// The scan buffer for a list of n patches in b blocks of EK_WAVE_SCAN_GROUP: arrays of n words
// (the outcome, the patch's starting patch, the split requests before it in its block, its
// entries in the next list, the entries before it in its block), then per block the sums before
// it of the requests and of the entries.
#define EK_WAVE_OUTCOMES(n) 0
#define EK_WAVE_ROOTS(n) (n)
#define EK_WAVE_REQUESTS_BEFORE(n) (2 * (n))
#define EK_WAVE_ENTRIES(n) (3 * (n))
#define EK_WAVE_ENTRIES_BEFORE(n) (4 * (n))
#define EK_WAVE_REQUEST_BLOCKS(n) (5 * (n))
#define EK_WAVE_ENTRY_BLOCKS(n, b) (5 * (n) + (b))
#define EK_WAVE_SCAN_WORDS(n, b) (5 * (n) + 2 * (b))

// Per starting patch of the pass (uint words): the patches it has made (itself included), and
// where its descendants' split requests start in the round's prefix sums.
#define EK_WAVE_ROOT_MADE 0
#define EK_WAVE_ROOT_FIRST_REQUEST 1
#define EK_WAVE_ROOT_WORDS 2

// A patch's outcome of a round (uint per patch), what the prefix sums count.
#define EK_WAVE_ENDED 0u
#define EK_WAVE_GOES_ON 1u
#define EK_WAVE_WANTS_SPLIT 2u

// The totals (uint words): int64 sums as (low, high) pairs of fixed-point values
// (shaders/fixed_point.glsl), rgb each, then plain counts.
#define EK_WAVE_ESCAPED 0
#define EK_WAVE_EXTINGUISHED 6
#define EK_WAVE_DROPPED 12
#define EK_WAVE_RECEIVED 18
#define EK_WAVE_REMOVED_POWER 24
#define EK_WAVE_REFLECTED 30
#define EK_WAVE_STEPS 36      // an int64 pair
#define EK_WAVE_CUT 38        // patches cut at the step cap
#define EK_WAVE_TORN 39       // patches ended torn at the level cap
#define EK_WAVE_REMOVED 40    // patches removed at a caustic
#define EK_WAVE_CROSSINGS 41  // orientation flips seen (kept or removed)
#define EK_WAVE_SPLIT 42      // splits granted
#define EK_WAVE_REFUSED 43    // splits refused by the budget
#define EK_WAVE_MAX_LEVEL 44  // the deepest split level made
#define EK_WAVE_TOTAL_WORDS 48

#endif
