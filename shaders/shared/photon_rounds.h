// The photon march's round buffer (render/transport/photons/photon_tracing_gpu.cpp,
// shaders/photon_trace.comp, shaders/photon_round.comp): one array of uint words, a header and then
// two lists of photon indices, each as long as the photon list. Round r marches the photons of list
// r & 1 (round 0: every photon, by a direct dispatch) and appends those still active to the other
// list; between rounds photon_round.comp turns the new count into the next round's dispatch
// arguments, so the host never needs the count. Word offsets, the same for C++ and GLSL.
#ifndef EIKON_SHARED_PHOTON_ROUNDS_H
#define EIKON_SHARED_PHOTON_ROUNDS_H

#define EK_ROUND_ARGS 0     // 3 words: glDispatchComputeIndirect's group counts x, y, z
#define EK_ROUND_STOP 3     // 1: the stop rule fired, the next round cuts its photons
#define EK_ROUND_COUNT 4    // 2 words: photons in list 0 and in list 1
#define EK_ROUND_MARCHED 6  // rounds that had photons to march (PhotonResultCpu::rounds)
#define EK_ROUND_HEADER 8   // words before list 0
#define EK_ROUND_GROUP 64   // invocations per work group of the tracing dispatch
// A dispatch may have at most 65535 groups per dimension (GL 4.3's minimum): larger counts are
// spread over y.
#define EK_ROUND_MAX_GROUPS_X 65535u

#endif
