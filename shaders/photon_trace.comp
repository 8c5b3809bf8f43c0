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

// ---- With EK_EXACT_MATH: the CPU twin's float arithmetic, where llvmpipe's built-ins round
// differently. The host asks for it on software rasterizers, where bit-identical results are
// cheap to have; hardware GPUs keep their fast built-ins (this exp runs in double precision,
// slow on most of them) and are compared with the twin within tolerances. ----
#ifdef EK_EXACT_MATH
// The twin compiles the shared code against glm and glibc: glm's dot is (x·x + y·y) + z·z, its
// length sqrt(dot), its normalize v · (1 / sqrt(dot)), its mix x·(1 − a) + y·a, its smoothstep
// (the spot falloff) t·t·(3 − 2t), and exp on a float is glibc's expf. llvmpipe's dot, length and normalize differ from those in the last bit
// for 10-30% of inputs, and its exp (a polynomial for exp2) for 70% (measured on Mesa 22.3); one
// such bit moves a photon across a voxel face or an octree node sooner or later. So these names
// are redefined below, before any shared file is included, as exactly those operation sequences.
// +, −, ×, ÷ and sqrt are correctly rounded on both sides and llvmpipe does not fuse a·b + c, so
// the sequences give the same bits. `precise` keeps Mesa's optimizer from rewriting them: without
// it a / sqrt(b), as in v / length(v), becomes a · rsqrt(b), which rounds differently, and sums
// may be reassociated. Other drivers may round their own way; the test shows it on llvmpipe.
float ekDot(vec3 a, vec3 b) {
    precise float r = a.x * b.x + a.y * b.y;
    r = r + a.z * b.z;
    return r;
}
float ekLength(vec3 v) {
    precise float r = sqrt(ekDot(v, v));
    return r;
}
vec3 ekNormalize(vec3 v) {
    precise float r = 1.0f / sqrt(ekDot(v, v));
    precise vec3 n = v * r;
    return n;
}
vec4 ekMix(vec4 x, vec4 y, float a) {
    precise vec4 r = x * (1.0f - a) + y * a;
    return r;
}
// glm's smoothstep: t = clamp((x − e0) / (e1 − e0), 0, 1), t · t · (3 − 2t).
float ekSmoothstep(float e0, float e1, float x) {
    precise float t = clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    precise float r = t * t * (3.0f - 2.0f * t);
    return r;
}

// 2^(i/32) as binary64 (low, high) words, minus i << 47 in the 64-bit pattern: glibc's
// __exp2f_data.tab (sysdeps/ieee754/flt-32/e_exp2f_data.c, EXP2F_TABLE_BITS = 5).
const uvec2 kExp2fTable[32] = uvec2[32](
    uvec2(0x00000000u, 0x3FF00000u), uvec2(0xD3158574u, 0x3FEFD9B0u),
    uvec2(0x6CF9890Fu, 0x3FEFB558u), uvec2(0xD0125B51u, 0x3FEF9301u),
    uvec2(0x3C7D517Bu, 0x3FEF72B8u), uvec2(0x3168B9AAu, 0x3FEF5487u),
    uvec2(0x6E756238u, 0x3FEF387Au), uvec2(0xF51FDEE1u, 0x3FEF1E9Du),
    uvec2(0x0A31B715u, 0x3FEF06FEu), uvec2(0x373AA9CBu, 0x3FEEF1A7u),
    uvec2(0x4C123422u, 0x3FEEDEA6u), uvec2(0x6061892Du, 0x3FEECE08u),
    uvec2(0xD5362A27u, 0x3FEEBFDAu), uvec2(0x569D4F82u, 0x3FEEB42Bu),
    uvec2(0xDD485429u, 0x3FEEAB07u), uvec2(0xB03A5585u, 0x3FEEA47Eu),
    uvec2(0x667F3BCDu, 0x3FEEA09Eu), uvec2(0xE8EC5F74u, 0x3FEE9F75u),
    uvec2(0x73EB0187u, 0x3FEEA114u), uvec2(0x994CCE13u, 0x3FEEA589u),
    uvec2(0x422AA0DBu, 0x3FEEACE5u), uvec2(0xB0CDC5E5u, 0x3FEEB737u),
    uvec2(0x82A3F090u, 0x3FEEC491u), uvec2(0xB23E255Du, 0x3FEED503u),
    uvec2(0x995AD3ADu, 0x3FEEE89Fu), uvec2(0xF2FB5E47u, 0x3FEEFF76u),
    uvec2(0xDD85529Cu, 0x3FEF199Bu), uvec2(0xDCEF9069u, 0x3FEF3720u),
    uvec2(0xDCFBA487u, 0x3FEF5818u), uvec2(0x337B9B5Fu, 0x3FEF7C97u),
    uvec2(0xA2A490DAu, 0x3FEFA4AFu), uvec2(0x5B6E4540u, 0x3FEFD076u)
);

// glibc's expf (sysdeps/ieee754/flt-32/e_expf.c, ARM optimized routines): exp(x) = 2^(k/32) ·
// 2^(r/32) with a cubic for the second factor, all in double and rounded to float once at the
// end. Every double operation is correctly rounded, so this reproduces expf bit for bit (glibc's
// FMA build fuses some of these products; that changes the double result by an ulp at most and
// the float result essentially never: 0 of 3·10^6 inputs sampled over [−103, 0) differ). The
// constants are glibc's, entered as bit patterns since GLSL has no hexadecimal float literals.
float ekExpf(float x) {
    if (isnan(x)) return x + x;
    if (x < -103.972076416015625f) return 0.0f;         // below log(2^-150): underflows
    if (x > 88.72283172607421875f) return x * 3.0e38f;  // above log(2^128): overflows
    const double invLn2N = packDouble2x32(uvec2(0x652B82FEu, 0x40471547u));  // 32 / ln 2
    const double shift = packDouble2x32(uvec2(0x00000000u, 0x43380000u));    // 0x1.8p+52
    const double c0 = packDouble2x32(uvec2(0x4B912394u, 0x3EBC6AF8u));
    const double c1 = packDouble2x32(uvec2(0x50FAC4F3u, 0x3F2EBFCEu));
    const double c2 = packDouble2x32(uvec2(0xFF0C52D6u, 0x3F962E42u));
    precise double z = invLn2N * double(x);
    // z + shift rounds z to the integer k (ties to even) in the low mantissa bits.
    precise double kd = z + shift;
    const uint ki = unpackDouble2x32(kd).x;
    kd -= shift;
    precise double r = z - kd;
    // s = 2^(k/32): the table entry with k added into the exponent (ki << 47 over 64 bits only
    // touches the high word, as ki << 15).
    const uvec2 t = kExp2fTable[ki & 31u];
    const double s = packDouble2x32(uvec2(t.x, t.y + (ki << 15u)));
    precise double p = c0 * r + c1;
    precise double r2 = r * r;
    precise double y = c2 * r + 1.0LF;
    y = p * r2 + y;
    return float(y * s);
}
vec3 ekExpf(vec3 x) {
    return vec3(ekExpf(x.x), ekExpf(x.y), ekExpf(x.z));
}

#define dot ekDot
#define length ekLength
#define normalize ekNormalize
#define mix ekMix
#define smoothstep ekSmoothstep
#define exp ekExpf
#endif
// ----

#include "volume_bindings.glsl"

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

// The CPU twin's toFixed, int64(llround(clamp(value · scale, ±4e18))), as the two's complement
// words (low, high). Every step is exact in double: the product is the same double as the CPU's
// (a float widened, times a double); trunc, the halfway test and the split by 2^32 lose nothing
// on integers below 2^62; so the result is the CPU's integer bit for bit. llround rounds halves
// away from zero, which GLSL's round() does not promise, hence the explicit test.
uvec2 toFixed(float value, double scale) {
    const double limit = 4.0e18LF;
    const double x = clamp(double(value) * scale, -limit, limit);
    double r = trunc(x);
    if (abs(x - r) >= 0.5LF) r += sign(x);
    const double high = floor(r * (1.0LF / 4294967296.0LF));  // |high| < 2^30: fits an int
    const double low = r - high * 4294967296.0LF;              // in [0, 2^32)
    return uvec2(uint(low), uint(int(high)));
}

// Adds the int64 v = (low, high) to the pair at words[at], words[at + 1], modulo 2^64.
// Order independence: the low word is a plain 32-bit sum, so after all adds it holds
// Σ low_i mod 2^32 whatever the order; each add that wraps it (old + low < old, unsigned) sends
// one carry to the high word, and since the low word ends below 2^32 the number of wraps is
// floor(Σ low_i / 2^32) in any order. The high word gets Σ high_i plus those carries, so the pair
// ends at Σ (high_i · 2^32 + low_i) mod 2^64: the int64 sum. Negative addends (the weighted
// direction) need nothing special: their high word is the sign-extended two's complement part,
// and modular addition of two's complement words is signed addition. The pair is torn while the
// dispatch runs (a carry may land before or after its low add), but it is read only after.
// A macro, not a function: atomicAdd needs the buffer variable itself, not a copy.
#define EK_ADD_FIXED(words, at, v)                                     \
    {                                                                  \
        const uint old_ = atomicAdd(words[(at)], (v).x);               \
        const uint high_ = (v).y + ((old_ + (v).x < old_) ? 1u : 0u);  \
        if (high_ != 0u) atomicAdd(words[(at) + 1], high_);            \
    }

void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir) {
    const ivec3 res = volumeResolution();
    const int base = ((voxel.z * res.y + voxel.y) * res.x + voxel.x) * 12;
    for (int c = 0; c < 3; ++c) {
        const uvec2 f = toFixed(fluxLength[c], depositScale[c]);
        EK_ADD_FIXED(deposits, base + 2 * c, f);
        const uvec2 d = toFixed(weightedDir[c], depositScale.w);
        EK_ADD_FIXED(deposits, base + 6 + 2 * c, d);
    }
}

void depositReceiverTexel(int index, vec3 flux) {
    for (int c = 0; c < 3; ++c) {
        const uvec2 f = toFixed(flux[c], totalScale[c]);
        EK_ADD_FIXED(receiverDeposits, index * 6 + 2 * c, f);
    }
}

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
    for (int c = 0; c < 3; ++c) {
        const uvec2 e = toFixed(extinguished[c], totalScale[c]);
        EK_ADD_FIXED(totals, 6 + 2 * c, e);
        const uvec2 l = toFixed(p.flux[c], totalScale[c]);
        EK_ADD_FIXED(totals, leftAt + 2 * c, l);
    }
    const uvec2 steps = uvec2(uint(int(p.direction.w)), 0u);
    EK_ADD_FIXED(totals, 18, steps);
    if (state == EK_PHOTON_CUT) atomicAdd(totals[20], 1u);
#endif
}
