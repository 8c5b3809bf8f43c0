#version 430 core
// Eikonal wavefront tracing on the GPU (render/transport/wavefront/wavefront_tracing_gpu.cpp),
// the CPU twin's rounds (shared/wavefront_rounds.h) on the shared patch code
// (shared/wavefront.h), one invocation per patch. Compiled three times:
//  - EK_WAVEFRONT_GENERATE: the starting patches of one light, in the layout the host chose
//    (planWavefronts), written with an empty tally to listOut[patchOffset + i]; the host reads
//    them back and sums their power to set the fixed-point scales before anything is deposited,
//    as the twin does;
//  - without a define: one round over listIn. Each patch runs patchRound; its outcome goes to the
//    scan buffer, its new state back to its entry, and a patch that ended adds its account
//    (extinguished, what it leaves as escaped, received or dropped, reflected) to the totals;
//  - EK_WAVEFRONT_SCATTER: after the prefix sums and grants (wavefront_scan.comp), writes the
//    next list: an entry that goes on at its offset, a granted split's four children
//    (patchChild) from it, the split counted against its starting patch's budget and its
//    account added to the totals.
// Every sum is a fixed-point one (fixed_point.glsl), so no order of the invocations changes a
// bit, and the list's order is the prefix sums', never the threads'.
#include "shared/wavefront_rounds.h"
layout(local_size_x = EK_WAVE_GROUP) in;

// With EK_EXACT_MATH: the CPU twin's float arithmetic, where llvmpipe's built-ins round
// differently (exact_math.glsl says how and why).
#ifdef EK_EXACT_MATH
#include "exact_math.glsl"
#endif

#include "volume_bindings.glsl"
#include "fixed_point.glsl"

// photons.h's deposits keep these channels: a wavefront carries only its own channels' power.
const vec3 photonChannels = vec3(1.0f);

// The hooks photons.h calls, declared before it and defined after (they need its struct).
vec4 fetchOctree(ivec3 voxel);
void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir);
void depositReceiverTexel(int index, vec3 flux);

#include "shared/material_index.h"
#include "shared/photons.h"
#include "shared/wavefront.h"

layout(std430, binding = EK_SSBO_WAVE_LIST_IN) buffer ListIn { GpuWavefrontEntry listIn[]; };
layout(std430, binding = EK_SSBO_WAVE_LIST_OUT) buffer ListOut { GpuWavefrontEntry listOut[]; };
// The outcomes, prefix sums and grants of the round (EK_WAVE_OUTCOMES and the arrays after it).
layout(std430, binding = EK_SSBO_WAVE_SCAN) buffer ScanBlock { uint scan[]; };
layout(std430, binding = EK_SSBO_WAVE_ROUNDS) buffer RoundsBlock { uint rounds[]; };
// Per starting patch: EK_WAVE_ROOT_* words.
layout(std430, binding = EK_SSBO_WAVE_ROOT_STATE) buffer RootBlock { uint rootState[]; };
layout(std430, binding = EK_SSBO_PHOTON_DEPOSITS) buffer DepositBlock { uint deposits[]; };
layout(std430, binding = EK_SSBO_RECEIVER_DEPOSITS) buffer ReceiverBlock {
    uint receiverDeposits[];
};

uniform int lightIndex;
uniform int lightGrid;  // EK_PHOTON_GRID_*
uniform int perSide;
uniform int patchOffset;
uniform int patchCount;  // a generating dispatch: the light's patches; else listIn's entries
uniform float fluxThreshold;
uniform int maxSteps;
uniform float splitVoxels;
uniform int maxLevel;
uniform float dt;
uniform int integrator;  // EK_WAVEFRONT_*
uniform int atCaustic;   // EK_WAVEFRONT_KEEP or EK_WAVEFRONT_REMOVE
uniform int samples;     // deposit chords per side
uniform float surfaceSlope;
// The CPU twin's scales, in double so that value · scale rounds the same way.
uniform dvec4 depositScale;  // rgb: power·length channels; w: weighted direction
uniform dvec3 totalScale;    // per channel, for the totals

// Never called: the wavefront reads no octree (photons.h's march does).
vec4 fetchOctree(ivec3 voxel) { return vec4(0.0f); }

#include "particle_deposits.glsl"

// Adds the fixed-point value of each channel of v to the int64 totals at word `at`.
void addTotal(int at, vec3 v) {
    for (int c = 0; c < 3; ++c) {
        const uvec2 f = toFixed(v[c], totalScale[c]);
        EK_ADD_FIXED(rounds, EK_WAVE_HEADER + at + 2 * c, f);
    }
}

// This invocation's patch, or −1: dispatches spread their groups over x and y.
int patchIndex() {
    const uint g = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x +
                   gl_GlobalInvocationID.x;
    return int(g) < patchCount ? int(g) : -1;
}

void main() {
    const int i = patchIndex();
    if (i < 0) return;
#if defined(EK_WAVEFRONT_GENERATE)
    GpuWavefrontEntry e;
    e.piece = generatePatch(lightIndex, lightGrid, perSide, i, fluxThreshold);
    e.tally.lost = vec4(0.0f);
    e.tally.reflected = vec4(0.0f);
    e.tally.root = ivec4(0);  // set by the host, which numbers the active ones
    listOut[patchOffset + i] = e;
#elif defined(EK_WAVEFRONT_SCATTER)
    const uint entries = scan[EK_WAVE_ENTRIES(patchCount) + i];
    if (entries == 0u) return;
    const int blocks = (patchCount + EK_WAVE_SCAN_GROUP - 1) / EK_WAVE_SCAN_GROUP;
    const int at = int(scan[EK_WAVE_ENTRIES_BEFORE(patchCount) + i] +
                       scan[EK_WAVE_ENTRY_BLOCKS(patchCount, blocks) + i / EK_WAVE_SCAN_GROUP]);
    GpuWavefrontEntry e = listIn[i];
    if (entries == 4u) {
        GpuWavefrontEntry child;
        child.tally.lost = vec4(0.0f);
        child.tally.reflected = vec4(0.0f);
        child.tally.root = e.tally.root;
        for (int c = 0; c < 4; ++c) {
            child.piece = patchChild(e.piece, c);
            listOut[at + c] = child;
        }
        atomicAdd(rootState[EK_WAVE_ROOT_WORDS * e.tally.root.x + EK_WAVE_ROOT_MADE], 4u);
        // The split patch's account; its power goes on in its children.
        addTotal(EK_WAVE_EXTINGUISHED, vec3(e.tally.lost));
        addTotal(EK_WAVE_REFLECTED, vec3(e.tally.reflected));
        atomicMax(rounds[EK_WAVE_HEADER + EK_WAVE_MAX_LEVEL], uint(int(e.piece.state.z) + 1));
        return;
    }
    // Refused a split: it goes on unsplit for good.
    if (scan[EK_WAVE_OUTCOMES(patchCount) + i] == EK_WAVE_WANTS_SPLIT) e.tally.lost.w = 1.0f;
    listOut[at] = e;
#else
    GpuWavefrontEntry e = listIn[i];
    int steps = 0;
    int crossings = 0;
    const int state =
        patchRound(e.piece, e.tally, EK_WAVE_ROUND_STEPS, maxSteps, splitVoxels, maxLevel, dt,
                   integrator, atCaustic, samples, surfaceSlope, steps, crossings);
    const uvec2 stepWords = uvec2(uint(steps), 0u);
    EK_ADD_FIXED(rounds, EK_WAVE_HEADER + EK_WAVE_STEPS, stepWords);
    if (crossings > 0) atomicAdd(rounds[EK_WAVE_HEADER + EK_WAVE_CROSSINGS], uint(crossings));
    scan[EK_WAVE_ROOTS(patchCount) + i] = uint(e.tally.root.x);
    if (state == EK_PHOTON_ACTIVE || state == EK_PATCH_WANTS_SPLIT) {
        scan[EK_WAVE_OUTCOMES(patchCount) + i] =
            state == EK_PHOTON_ACTIVE ? EK_WAVE_GOES_ON : EK_WAVE_WANTS_SPLIT;
        listIn[i] = e;
        return;
    }
    scan[EK_WAVE_OUTCOMES(patchCount) + i] = EK_WAVE_ENDED;
    // The CPU twin's account of a patch that ended: the power it carries is escaped, received
    // or dropped (cut, removed and torn included).
    const vec3 power = vec3(e.piece.power);
    addTotal(EK_WAVE_EXTINGUISHED, vec3(e.tally.lost));
    addTotal(state == EK_PHOTON_ESCAPED    ? EK_WAVE_ESCAPED
             : state == EK_PHOTON_RECEIVED ? EK_WAVE_RECEIVED
                                           : EK_WAVE_DROPPED,
             power);
    addTotal(EK_WAVE_REFLECTED, vec3(e.tally.reflected));
    if (state == EK_PHOTON_CUT) atomicAdd(rounds[EK_WAVE_HEADER + EK_WAVE_CUT], 1u);
    if (state == EK_PATCH_TORN) atomicAdd(rounds[EK_WAVE_HEADER + EK_WAVE_TORN], 1u);
    if (state == EK_PATCH_REMOVED) {
        atomicAdd(rounds[EK_WAVE_HEADER + EK_WAVE_REMOVED], 1u);
        addTotal(EK_WAVE_REMOVED_POWER, power);
    }
#endif
}
