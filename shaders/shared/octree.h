// The octree of Sun et al. 2008 (§4.2, amended in §5.3) as a dense volume, the same on the GPU and
// in the CPU twin. Functions only; needs from the includer `vec4 fetchPyramid(int index)`, the
// (n_min, n_max, κ_min, κ_max) stored at a flat pyramid index (pyramidNodeIndex), κ being the
// largest channel of the extinction at voxel centres.
//
// Pyramid: level 0 holds one node per voxel: the range of n over the voxel's 5×5×5
// neighbourhood (pyramidLeafRange below says why); a node of level k
// covers 2^k voxels per axis, so level k has ceil(resolution / 2^k) nodes per axis (the last node
// of an axis that is not a power of two covers fewer voxels), up to the coarsest level K, a
// single node covering the whole volume. All levels lie in one flat array, level after level,
// each x fastest, then y, then z.
//
// Labelling rule (one reading of §4.2 with the §5.3 amendment, written down here because the
// paper leaves the interplay of the two tolerances open). For each voxel, walk the nodes that
// contain it from level K down to level 1; the first node whose range r = n_max − n_min satisfies
//   r < ε   gives the label k and Δs_max = EK_UNLIMITED_STEP ("infinity"), or
//   r < ε'  gives the label k and Δs_max = stepLimit (the user's limit, 8 voxels by default).
// A voxel is labelled once: the coarsest qualifying node wins, as in §4.2, so a node with a
// little variation (ε ≤ r < ε') is preferred over finer, flat nodes — the "intermediate step
// sizes" §5.3 introduces: larger than the finer nodes' boundaries allow, yet capped.
// When no node of level 1 or coarser has r < ε', the voxel gets label 0 and Δs_max = minStep
// (the user's minimum step): near strong variation, marching takes the minimum step.
// Extension (not in the paper, off when κ_tol ≤ 0): a node qualifies only if, besides, its
// extinction varies by less than κ_tol in optical depth across it, (κ_max − κ_min) × its edge
// < κ_tol. A photon step takes κ at its midpoint for the whole step, which is exact only where κ
// is constant: without this, a flat n lets a photon cross a thin absorber, or skip it, in one
// long step.
// Steps are in scene units.

#define EK_UNLIMITED_STEP 1e30f

// Nodes per axis at pyramid level `level`. Shifts, not divisions: the counts are positive, so
// x >> k is x / 2^k, and octreeLabel takes these for every level of every voxel (with divisions
// by a variable the CPU twin's octree stage at 128³ took 388 ms on one core, with shifts 240).
ivec3 pyramidLevelSize(ivec3 res, int level) {
    return (res + ivec3((1 << level) - 1)) >> level;
}

// Number of levels, 0..K: K is the first level whose single node covers every axis.
int pyramidLevelCount(ivec3 res) {
    const int longest = max(res.x, max(res.y, res.z));
    int top = 0;
    while ((1 << top) < longest) ++top;
    return top + 1;
}

int pyramidNodeCount(ivec3 res, int level) {
    const ivec3 s = pyramidLevelSize(res, level);
    return s.x * s.y * s.z;
}

// Flat index of the first node of `level`.
int pyramidLevelOffset(ivec3 res, int level) {
    int offset = 0;
    for (int k = 0; k < level; ++k) offset += pyramidNodeCount(res, k);
    return offset;
}

int pyramidNodeIndex(ivec3 res, int level, ivec3 node) {
    const ivec3 s = pyramidLevelSize(res, level);
    return pyramidLevelOffset(res, level) + (node.z * s.y + node.y) * s.x + node.x;
}

#ifdef EK_OCTREE_LEAF_RANGE
// Level 0 (with EK_OCTREE_LEAF_RANGE; needs `float fetchIndex(ivec3 voxel)`, n at a voxel
// centre, and `vec2 fetchKappaRange(ivec3 voxel)`, bounds on the extinction's largest channel
// within a voxel of that centre, optics.h voxelExtinctionRange):
// (n_min, n_max) over the voxels within two of `voxel` along every axis, clamped at the faces. A
// march inside a voxel samples ∇n trilinearly from centres up to one voxel away, and each of
// those is a central difference reaching one voxel further: n up to two voxels away bends a path
// inside this voxel. A node is flat only if all of that is flat; with n at its own centres alone,
// a voxel beside a sharp rim looked flat, allowed an unlimited step, and the rim's ∇n sampled at
// its start reversed photons. (κ_min, κ_max) over the voxels within one: κ is sampled
// trilinearly, with no difference.
vec4 pyramidLeafRange(ivec3 res, ivec3 voxel) {
    vec4 range = vec4(EK_UNLIMITED_STEP, -EK_UNLIMITED_STEP, EK_UNLIMITED_STEP, -EK_UNLIMITED_STEP);
    for (int dz = -2; dz <= 2; ++dz)
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                const ivec3 v = clamp(voxel + ivec3(dx, dy, dz), ivec3(0), res - ivec3(1));
                const float n = fetchIndex(v);
                range.x = min(range.x, n);
                range.y = max(range.y, n);
                if (abs(dx) <= 1 && abs(dy) <= 1 && abs(dz) <= 1) {
                    const vec2 kappa = fetchKappaRange(v);
                    range.z = min(range.z, kappa.x);
                    range.w = max(range.w, kappa.y);
                }
            }
    return range;
}
#endif

// The ranges of node `node` at level ≥ 1 from its up to 8 children at level − 1; children past
// the edge of a non-power-of-two axis are clamped onto the last one, which changes neither the
// minima nor the maxima.
vec4 pyramidNodeFromChildren(ivec3 res, int level, ivec3 node) {
    const ivec3 last = pyramidLevelSize(res, level - 1) - ivec3(1);
    vec4 range = vec4(EK_UNLIMITED_STEP, -EK_UNLIMITED_STEP, EK_UNLIMITED_STEP, -EK_UNLIMITED_STEP);
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const ivec3 child = min(node * ivec3(2) + ivec3(dx, dy, dz), last);
                const vec4 c = fetchPyramid(pyramidNodeIndex(res, level - 1, child));
                range = vec4(min(range.x, c.x), max(range.y, c.y), min(range.z, c.z),
                             max(range.w, c.w));
            }
    return range;
}

// The walk of octreeLabel over levels top..1 for the voxels of level-1 node `node1` (voxel >> 1).
// Every level above 0 sees the same nodes for the eight voxels of a level-1 node, so the CPU twin
// walks once for the eight. The label it finds (octreeLabel's), or x = −1 where no node of level 1
// or coarser qualifies.
vec4 octreeLabelAboveLeaves(ivec3 res, ivec3 node1, float epsilon, float epsilonPrime,
                            float stepLimit, float kappaTolerance, float voxelLength) {
    const int top = pyramidLevelCount(res) - 1;
    // The first node of each level, walked down from past the top: pyramidNodeIndex would sum
    // the levels below anew at every level (half of the CPU twin's octree stage at 48×64×48).
    int offset = pyramidLevelOffset(res, top) + pyramidNodeCount(res, top);
    for (int level = top; level >= 1; --level) {
        offset -= pyramidNodeCount(res, level);
        const ivec3 size = pyramidLevelSize(res, level);
        const ivec3 node = node1 >> (level - 1);  // node1 ≥ 0: voxel / 2^level
        const vec4 r = fetchPyramid(offset + (node.z * size.y + node.y) * size.x + node.x);
        if (kappaTolerance > 0.0f &&
            !((r.w - r.z) * (float(1 << level) * voxelLength) < kappaTolerance))
            continue;
        const float range = r.y - r.x;
        if (range < epsilon) return vec4(float(level), EK_UNLIMITED_STEP, r.x, r.y);
        if (range < epsilonPrime) return vec4(float(level), stepLimit, r.x, r.y);
    }
    return vec4(-1.0f, 0.0f, 0.0f, 0.0f);
}

// x: label (level, as a float); y: Δs_max in scene units; z, w: n_min, n_max of the labelled
// node. See the rule at the top of this file; voxelLength is the edge of a voxel (scene units)
// that κ_tol's optical depth is measured with. `above` is octreeLabelAboveLeaves of the voxel's
// level-1 node.
vec4 octreeLabelFrom(vec4 above, ivec3 res, ivec3 voxel, float minStep) {
    if (above.x >= 0.0f) return above;
    const vec4 r0 = fetchPyramid(pyramidNodeIndex(res, 0, voxel));
    return vec4(0.0f, minStep, r0.x, r0.y);
}

vec4 octreeLabel(ivec3 res, ivec3 voxel, float epsilon, float epsilonPrime, float stepLimit,
                 float minStep, float kappaTolerance, float voxelLength) {
    const vec4 above = octreeLabelAboveLeaves(res, voxel >> 1, epsilon, epsilonPrime, stepLimit,
                                              kappaTolerance, voxelLength);
    return octreeLabelFrom(above, res, voxel, minStep);
}
