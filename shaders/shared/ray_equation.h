// The ray equation d/ds(n dx/ds) = ∇n (Sun et al. 2008, eqs. 4-5), stepped by one of four
// integrators, the same for photons (photons.h) and curved view rays (view_march.h), on the GPU
// and in the CPU twin. Functions only; needs sampling.h (sampleVolume, EK_GRADIENT_SLOT: the ∇n
// volume, xyz = ∇n, w = n, sampled trilinearly).
//
// With v = n dx/ds and the optical parameter τ (dτ = ds/n) the equation is the separable
// Hamiltonian system dx/dτ = v, dv/dτ = n∇n = ∇(n²)/2 (H = |v|²/2 − n²/2, zero on a ray). A step
// is asked for as an arc length Δs and taken as Δτ = Δs/n, so that every integrator moves about
// Δs along the ray and a step costs what its force evaluations cost:
//   EK_RAY_EULER     the paper's explicit Euler: x += (Δs/n) v, v += Δs ∇n, both at x. First
//                    order; one evaluation (at x).
//   EK_RAY_MIDPOINT  explicit midpoint (RK2): the force at x + (Δτ/2) v after a half Euler step.
//                    Second order; two evaluations.
//   EK_RAY_RK4       classical Runge–Kutta. Fourth order where the force is smooth; the ∇n volume
//                    is sampled trilinearly, so its force has kinks at every voxel face and RK4
//                    is of second order there (BENCHMARKS.md measures it). Four evaluations.
//   EK_RAY_VERLET    Störmer–Verlet in τ, drift-kick-drift: x½ = x + (Δτ/2) v, v += Δτ F(x½),
//                    x += (Δτ/2) v. Second order and one evaluation per step, at x½: its Δτ comes
//                    from |v| (= n on the ray) instead of n at x. With a fixed Δτ and a force that
//                    is a gradient it is symplectic and time-reversible (no secular drift of H);
//                    here Δτ varies with |v| and the trilinear ∇n volume is a gradient only to
//                    O(h²), so those hold only approximately.

#define EK_RAY_EULER 0
#define EK_RAY_MIDPOINT 1
#define EK_RAY_RK4 2
#define EK_RAY_VERLET 3

// xyz: ∇n; w: n, at world point x.
vec4 gradientAt(vec3 x) {
    return sampleVolume(EK_GRADIENT_SLOT, worldToVolumeIndex(x));
}

// n∇n, the force of the τ form, from a gradient sample g (xyz: ∇n, w: n).
vec3 rayForce(vec4 g) {
    return g.w * vec3(g);
}

// What a step needs at its start x: the gradient sample there (xyz: ∇n, w: n), except for
// Verlet, which evaluates nothing at x: w holds |v| (= n on the ray) and xyz is unused.
vec4 rayStepStart(int integrator, vec3 x, vec3 v) {
    if (integrator == EK_RAY_VERLET) return vec4(0.0f, 0.0f, 0.0f, length(v));
    return gradientAt(x);
}

// One step of arc length ds from (x, v) with `integrator`, g0 = rayStepStart(integrator, x, v);
// x and v become the step's end. Returns false where the medium is degenerate (n ≤ 10⁻⁶ where
// it was sampled, or |v| ≈ 0): the ray cannot go on, and x, v are left as they were.
bool rayAdvance(int integrator, EK_INOUT(vec3) x, EK_INOUT(vec3) v, float ds, vec4 g0) {
    if (!(g0.w > 1e-6f)) return false;
    const float dtau = ds / g0.w;
    if (integrator == EK_RAY_VERLET) {
        const vec3 xHalf = x + (0.5f * dtau) * v;
        const vec4 g = gradientAt(xHalf);
        if (!(g.w > 1e-6f)) return false;
        v = v + dtau * rayForce(g);
        x = xHalf + (0.5f * dtau) * v;
        return true;
    }
    if (integrator == EK_RAY_EULER) {
        x = x + (ds / g0.w) * v;
        v = v + ds * vec3(g0);
        return true;
    }
    const vec3 f0 = rayForce(g0);
    if (integrator == EK_RAY_MIDPOINT) {
        const vec3 vMid = v + (0.5f * dtau) * f0;
        const vec3 fMid = rayForce(gradientAt(x + (0.5f * dtau) * v));
        x = x + dtau * vMid;
        v = v + dtau * fMid;
        return true;
    }
    // RK4: stages (x_i, v_i) at τ, τ + Δτ/2, τ + Δτ/2, τ + Δτ; dx/dτ = v_i, dv/dτ = F(x_i).
    const vec3 v2 = v + (0.5f * dtau) * f0;
    const vec3 f2 = rayForce(gradientAt(x + (0.5f * dtau) * v));
    const vec3 v3 = v + (0.5f * dtau) * f2;
    const vec3 f3 = rayForce(gradientAt(x + (0.5f * dtau) * v2));
    const vec3 v4 = v + dtau * f3;
    const vec3 f4 = rayForce(gradientAt(x + dtau * v3));
    const float sixth = dtau * (1.0f / 6.0f);
    x = x + sixth * (v + 2.0f * v2 + 2.0f * v3 + v4);
    v = v + sixth * (f0 + 2.0f * f2 + 2.0f * f3 + f4);
    return true;
}
