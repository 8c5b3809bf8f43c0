// Fixed-point sums on the GPU, the CPU twin's rule (render/transport/fixed_point.h): values
// become int64 integers with the twin's rounding, and sums of them are exact and independent of
// the order of the additions, on any GPU schedule. GLSL 4.30 has no 64-bit integers or atomics,
// so each int64 is a pair of uint words (low, high) holding its two's complement.
// Used by photon_trace.comp and plane_sweep.comp.
#ifndef EIKON_FIXED_POINT_GLSL
#define EIKON_FIXED_POINT_GLSL

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

#endif
