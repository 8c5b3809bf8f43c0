#ifndef EIKON_EXACT_MATH_GLSL
#define EIKON_EXACT_MATH_GLSL
// The CPU twin's float arithmetic, for passes compiled with EK_EXACT_MATH (photon_trace.comp,
// plane_sweep.comp), where llvmpipe's built-ins round differently: included before any shared
// file, it renames the built-ins whose rounding differs. The host asks for it on software
// rasterizers, where bit-identical results are cheap to have; hardware GPUs keep their fast
// built-ins (this exp runs in double precision, slow on most of them) and are compared with the
// twin within tolerances.
//
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
vec3 ekMix(vec3 x, vec3 y, float a) {
    precise vec3 r = x * (1.0f - a) + y * a;
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
