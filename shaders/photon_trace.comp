#version 430 core
// Photon tracing, steps 4 and 5 of Sun et al. 2008 (shaders/shared/photons.h), one invocation
// per photon (render/transport/photons/photon_tracing_gpu.cpp). Compiled twice:
//  - with EK_PHOTON_GENERATE: generates one light's photons, in the layout the host chose
//    (photonGrid, run once in the CPU twin's planPhotons), and writes their starting states.
//    The host sums their flux to set the fixed-point scales before anything is deposited,
//    exactly as the CPU twin (render/transport/photons/photon_tracing_cpu.cpp) does;
//  - without: one round of the march (shared/photon_rounds.h): marches each photon of the round
//    by up to roundSteps steps, depositing every segment piece into the fixed-point radiance
//    volume; appends the photons still active to the next round's list, and adds the bookkeeping
//    of each photon that ended (or was cut) to the fixed-point totals.
//
// The CPU twin sums int64 values; GLSL 4.30 has no 64-bit integers or atomics, so each int64 is
// a pair of uint words (low, high) holding its two's complement, and a sum is kept exactly
// modulo 2^64 by EK_ADD_FIXED below.
layout(local_size_x = 64) in;

// With EK_EXACT_MATH: the CPU twin's float arithmetic, where llvmpipe's built-ins round
// differently (exact_math.glsl says how and why).
#ifdef EK_EXACT_MATH
#include "exact_math.glsl"
#endif

#include "volume_bindings.glsl"
#include "fixed_point.glsl"

// The colour channels this pass deposits (photons.h): (1, 1, 1), or under dispersion one
// channel's 1 per pass, the pass tracing through that channel's ∇n volume.
uniform vec3 photonChannels;

// The hooks photons.h calls, declared before it and defined after (they need its struct).
vec4 fetchOctree(ivec3 voxel);
void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir);
void depositReceiverTexel(int index, vec3 flux);

#include "shared/photons.h"
#include "shared/photon_rounds.h"

// No other volume pass uses EK_UNIT_OCTREE.
layout(binding = EK_UNIT_OCTREE) uniform sampler3D octreeTex;
// Photons of all lights, light after light in the CPU twin's order. A generating dispatch covers
// photons photonFirst .. photonFirst + photonCount − 1 of light lightIndex, stored from
// photons[photonOffset]; a tracing dispatch covers photons[photonFirst ..] of all lights.
layout(std430, binding = EK_SSBO_PHOTONS) buffer PhotonBlock { GpuPhoton photons[]; };
// Per voxel (x fastest) 6 int64 sums as (low, high) word pairs: r, g, b, then the weighted
// direction x, y, z.
layout(std430, binding = EK_SSBO_PHOTON_DEPOSITS) buffer DepositBlock { uint deposits[]; };
// int64 pairs: escaped rgb, extinguished rgb, dropped rgb, steps, cut photons, received rgb.
layout(std430, binding = EK_SSBO_PHOTON_TOTALS) buffer TotalsBlock { uint totals[]; };
// Per receiver map texel (render/receiver_map.h) 3 int64 flux sums as (low, high) word pairs.
layout(std430, binding = EK_SSBO_RECEIVER_DEPOSITS) buffer ReceiverBlock {
    uint receiverDeposits[];
};
// The round header and the two lists of active photon indices (shared/photon_rounds.h).
layout(std430, binding = EK_SSBO_PHOTON_ROUNDS) buffer RoundBlock { uint rounds[]; };
// Per photon: xyz the flux it has lost to extinction in the rounds so far, carried between rounds
// so that its bookkeeping adds the same float sum as one uninterrupted march.
layout(std430, binding = EK_SSBO_PHOTON_EXTINGUISHED) buffer ExtinguishedBlock {
    vec4 photonExtinguished[];
};

uniform int lightIndex;
uniform int lightGrid;  // EK_PHOTON_GRID_*
uniform int photonsPerSide;
uniform int photonOffset;
uniform int photonFirst;
uniform int photonCount;
uniform uint seed;
uniform uint frame;
uniform float fluxThreshold;
uniform float minStep;
uniform int integrator;   // EK_RAY_* (shared/ray_equation.h)
uniform int roundSteps;   // steps of this round (render/transport/photons/photon_tracing.h photonRoundSteps)
uniform bool lastRound;   // the step cap: photons still active after this round are cut
uniform bool fromList;    // false: round 0, photons[photonFirst ..]; true: list listIn
uniform int listIn;       // the list this round reads (0 or 1); it appends to the other
uniform int listCapacity;  // indices per list: the photon count
// The CPU twin's scales, in double so that value · scale rounds the same way.
uniform dvec4 depositScale;  // rgb: flux·length channels; w: weighted direction
uniform dvec3 totalScale;    // per channel, for the totals

vec4 fetchOctree(ivec3 voxel) { return texelFetch(octreeTex, voxel, 0); }

#include "particle_deposits.glsl"

// The photon this invocation works on, or −1 for none. Direct dispatches cover photons
// photonFirst .. photonFirst + photonCount − 1 in x; an indirect one (a round after the first)
// covers its list, in groups spread over x and y (shared/photon_rounds.h).
int photonIndex() {
    const uint g = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x +
                   gl_GlobalInvocationID.x;
#ifndef EK_PHOTON_GENERATE
    if (fromList) {
        if (g >= rounds[EK_ROUND_COUNT + listIn]) return -1;
        return int(rounds[EK_ROUND_HEADER + listIn * listCapacity + int(g)]);
    }
#endif
    return int(g) < photonCount ? photonFirst + int(g) : -1;
}

void main() {
    const int i = photonIndex();
    if (i < 0) return;
#ifdef EK_PHOTON_GENERATE
    photons[photonOffset + i] = generatePhoton(lightIndex, lightGrid, photonsPerSide, i, seed,
                                               frame, fluxThreshold);
#else
    GpuPhoton p = photons[i];
    if (int(p.position.w) != EK_PHOTON_ACTIVE) return;
    vec3 extinguished = fromList ? photonExtinguished[i].xyz : vec3(0.0f);
    const bool stop = rounds[EK_ROUND_STOP] != 0u;
    if (!stop) marchPhoton(p, minStep, integrator, roundSteps, extinguished);
    const bool still = int(p.position.w) == EK_PHOTON_ACTIVE;
    if (still && !stop && !lastRound) {
        // Compaction: the photon's state stays in its slot (downloads keep index order); only its
        // index goes into the next list. The append order varies from run to run, which changes
        // nothing: photons are independent and every sum is an integer one.
        photons[i] = p;
        photonExtinguished[i] = vec4(extinguished, 0.0f);
        const int listOut = 1 - listIn;
        const uint at = atomicAdd(rounds[EK_ROUND_COUNT + listOut], 1u);
        rounds[EK_ROUND_HEADER + listOut * listCapacity + int(at)] = uint(i);
        return;
    }
    // Still active at the step cap or when the stop rule fired: cut, as the CPU twin does.
    if (still) p.position.w = float(EK_PHOTON_CUT);
    photons[i] = p;
    // The CPU twin's per-photon bookkeeping: the flux left in the photon is escaped, received or
    // dropped.
    const int state = int(p.position.w);
    const int leftAt = state == EK_PHOTON_ESCAPED ? 0 : state == EK_PHOTON_RECEIVED ? 22 : 12;
    const vec3 lost = extinguished * photonChannels;
    const vec3 left = vec3(p.flux) * photonChannels;
    for (int c = 0; c < 3; ++c) {
        const uvec2 e = toFixed(lost[c], totalScale[c]);
        EK_ADD_FIXED(totals, 6 + 2 * c, e);
        const uvec2 l = toFixed(left[c], totalScale[c]);
        EK_ADD_FIXED(totals, leftAt + 2 * c, l);
    }
    const uvec2 steps = uvec2(uint(int(p.direction.w)), 0u);
    EK_ADD_FIXED(totals, 18, steps);
    if (state == EK_PHOTON_CUT) atomicAdd(totals[20], 1u);
#endif
}
