#version 430 core
// Between two rounds of the wavefront's trace (shared/wavefront_rounds.h,
// render/transport/wavefront/wavefront_tracing_gpu.cpp): the prefix sums over the outcomes the
// round wrote (wavefront_trace.comp) and the patch budget's grants, all on the GPU. Stages, in
// the order the host runs them:
//  - EK_WAVE_STAGE_BLOCKS, a group per block of EK_WAVE_SCAN_GROUP patches: each patch's
//    exclusive prefix sum within its block of the words at `source` (or, with `requests`, of
//    whether its outcome asks for a split) into `target`, and the block's sum into `blocks`;
//  - EK_WAVE_STAGE_TOTALS, one group: the blocks' exclusive prefix sums in place, and the sum of
//    all into the round header's word `totalWord`;
//  - EK_WAVE_STAGE_FIRSTS: the first patch of each starting patch's run in the list writes
//    where that run's requests start in the prefix sums;
//  - EK_WAVE_STAGE_GRANTS: each patch's entries in the next list: 0 if it ended, 1 if it goes on
//    or its split is refused, 4 if granted (the first requests of its starting patch's run while
//    its patches made stay within `budget`).
// Requests are summed (BLOCKS, TOTALS), then FIRSTS and GRANTS, then the entries are summed,
// their total being the next list's length; the scatter (wavefront_trace.comp) places them.
#include "shared/bindings.h"
#include "shared/wavefront_rounds.h"

#define EK_WAVE_STAGE_BLOCKS 0
#define EK_WAVE_STAGE_TOTALS 1
#define EK_WAVE_STAGE_FIRSTS 2
#define EK_WAVE_STAGE_GRANTS 3

layout(local_size_x = EK_WAVE_SCAN_GROUP) in;

layout(std430, binding = EK_SSBO_WAVE_SCAN) buffer ScanBlock { uint scan[]; };
layout(std430, binding = EK_SSBO_WAVE_ROUNDS) buffer RoundsBlock { uint rounds[]; };
layout(std430, binding = EK_SSBO_WAVE_ROOT_STATE) buffer RootBlock { uint rootState[]; };

uniform int stage;
uniform int patchCount;  // entries of the list the round traced
uniform int source;      // BLOCKS: the words summed (with `requests`, the outcomes)
uniform bool requests;
uniform int target;      // BLOCKS: where the in-block prefix sums go
uniform int blocks;      // BLOCKS, TOTALS: where the blocks' sums are
uniform int totalWord;   // TOTALS: the header word that gets the sum of all
uniform uint budget;     // GRANTS: patches a starting patch may make, itself included

shared uint partial[EK_WAVE_SCAN_GROUP];

// The exclusive prefix sum of `value` over the group (Hillis-Steele in shared memory); every
// invocation of the group must call it. total: the group's sum.
uint groupExclusiveScan(uint value, out uint total) {
    const uint t = gl_LocalInvocationID.x;
    partial[t] = value;
    barrier();
    for (uint offset = 1u; offset < uint(EK_WAVE_SCAN_GROUP); offset *= 2u) {
        const uint add = t >= offset ? partial[t - offset] : 0u;
        barrier();
        partial[t] += add;
        barrier();
    }
    total = partial[EK_WAVE_SCAN_GROUP - 1];
    return partial[t] - value;
}

// The split requests before patch i in the whole list.
uint requestsBefore(int i) {
    return scan[EK_WAVE_REQUESTS_BEFORE(patchCount) + i] +
           scan[EK_WAVE_REQUEST_BLOCKS(patchCount) + i / EK_WAVE_SCAN_GROUP];
}

void main() {
    const uint t = gl_LocalInvocationID.x;
    // Groups spread over x and y (a dispatch has at most 65535 groups in x).
    const int group = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);
    const int i = group * EK_WAVE_SCAN_GROUP + int(t);
    const int blockCount = (patchCount + EK_WAVE_SCAN_GROUP - 1) / EK_WAVE_SCAN_GROUP;
    uint total;
    if (stage == EK_WAVE_STAGE_BLOCKS) {
        uint value = 0u;
        if (i < patchCount) {
            const uint word = scan[source + i];
            value = requests ? (word == EK_WAVE_WANTS_SPLIT ? 1u : 0u) : word;
        }
        const uint before = groupExclusiveScan(value, total);
        if (i < patchCount) scan[target + i] = before;
        if (t == 0u && group < blockCount) scan[blocks + group] = total;
    } else if (stage == EK_WAVE_STAGE_TOTALS) {
        // Each invocation takes a run of blocks, sums it, and after the group's scan writes the
        // run's exclusive prefix sums in place.
        const int run = (blockCount + EK_WAVE_SCAN_GROUP - 1) / EK_WAVE_SCAN_GROUP;
        const int first = int(t) * run;
        const int last = min(first + run, blockCount);
        uint sum = 0u;
        for (int b = first; b < last; ++b) sum += scan[blocks + b];
        uint before = groupExclusiveScan(sum, total);
        for (int b = first; b < last; ++b) {
            const uint own = scan[blocks + b];
            scan[blocks + b] = before;
            before += own;
        }
        if (t == 0u) rounds[totalWord] = total;
    } else if (stage == EK_WAVE_STAGE_FIRSTS) {
        if (i >= patchCount) return;
        const uint root = scan[EK_WAVE_ROOTS(patchCount) + i];
        if (i == 0 || scan[EK_WAVE_ROOTS(patchCount) + i - 1] != root)
            rootState[EK_WAVE_ROOT_WORDS * root + EK_WAVE_ROOT_FIRST_REQUEST] = requestsBefore(i);
    } else {
        if (i >= patchCount) return;
        const uint outcome = scan[EK_WAVE_OUTCOMES(patchCount) + i];
        uint entries = outcome == EK_WAVE_ENDED ? 0u : 1u;
        if (outcome == EK_WAVE_WANTS_SPLIT) {
            const uint root = scan[EK_WAVE_ROOTS(patchCount) + i];
            const uint made = rootState[EK_WAVE_ROOT_WORDS * root + EK_WAVE_ROOT_MADE];
            const uint rank =
                requestsBefore(i) -
                rootState[EK_WAVE_ROOT_WORDS * root + EK_WAVE_ROOT_FIRST_REQUEST];
            const uint granted = made < budget ? (budget - made) / 4u : 0u;
            entries = rank < granted ? 4u : 1u;
            atomicAdd(rounds[EK_WAVE_HEADER + (entries == 4u ? EK_WAVE_SPLIT : EK_WAVE_REFUSED)],
                      1u);
        }
        scan[EK_WAVE_ENTRIES(patchCount) + i] = entries;
    }
}
