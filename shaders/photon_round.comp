#version 430 core
// Between two rounds of the photon march (render/transport/photons/photon_tracing_gpu.cpp), one invocation: the
// photons the last round appended become the next round's dispatch arguments, the stop rule is
// checked, and the list the last round read is emptied for the round after to append to. All on
// the GPU: the host issues the rounds without reading any count back.
layout(local_size_x = 1) in;

#include "shared/bindings.h"
#include "shared/photon_rounds.h"

layout(std430, binding = EK_SSBO_PHOTON_ROUNDS) buffer RoundBlock { uint rounds[]; };

uniform int listIn;      // the list the last round read (0 or 1); it appended to the other
uniform uint stopCount;  // fewer active photons than this end the march (0: never)

void main() {
    const uint done = rounds[EK_ROUND_COUNT + listIn];
    const uint next = rounds[EK_ROUND_COUNT + 1 - listIn];
    if (done > 0u) rounds[EK_ROUND_MARCHED] += 1u;
    rounds[EK_ROUND_COUNT + listIn] = 0u;
    // The CPU twin's rule (render/transport/photons/photon_tracing_cpu.cpp): a round that cut appended nothing, so
    // the flag clears itself after one round.
    rounds[EK_ROUND_STOP] = (next > 0u && next < stopCount) ? 1u : 0u;
    const uint groups = (next + uint(EK_ROUND_GROUP) - 1u) / uint(EK_ROUND_GROUP);
    const uint x = min(groups, EK_ROUND_MAX_GROUPS_X);
    rounds[EK_ROUND_ARGS] = x;
    rounds[EK_ROUND_ARGS + 1] = x > 0u ? (groups + x - 1u) / x : 1u;
    rounds[EK_ROUND_ARGS + 2] = 1u;
}
