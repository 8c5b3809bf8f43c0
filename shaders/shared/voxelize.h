// Voxelization of closed triangle meshes to fractional coverage (Sun et al. 2008 §4.1), the same
// on the GPU and in the CPU twin (render/voxelize.h). Functions only; needs platform.h and, from
// the includer, the hooks `void toggleSample(int column, int k)` (XOR bit k of fine column
// `column`, x fastest) and `uint fetchInsideWord(int index)` (word index of the scanned bits,
// column · voxelizeWordsPerColumn + word).
//
// Inside/outside is a parity count along z on a sample grid `EK_VOXELIZE_SUPERSAMPLE` times finer
// than the render volume per axis (the "fine grid"; sample (i, j, k) at the centre of fine cell
// (i, j, k)). A closed mesh crosses every fine column (i, j) an even number of times, so:
//  1. toggle: every triangle whose xy projection covers the column's centre flips ONE bit, that of
//     the first sample above the crossing (XOR: order-independent, so the GPU's atomics give the
//     same bits whatever the order);
//  2. scan: a prefix XOR up each column turns the flips into inside = 1;
//  3. count: a render voxel's coverage is the fraction of its 4×4×4 = 64 samples inside.
// Sun et al. take 64 samples only where a voxel's 3×3×3 neighbourhood is not uniform and the
// centre test elsewhere; counting every voxel costs little here (one 4-bit field per fine column
// and voxel) and also catches features thinner than a voxel inside a uniform neighbourhood.
//
// A column centre exactly on an edge or vertex of the projection must be counted by exactly one
// of the triangles there, or the parity breaks along a whole column. The rule: a sample on an edge
// belongs to the triangle on the left of the edge's canonical direction (from its
// lexicographically smaller (x, y) end); equivalently, the sample is perturbed infinitesimally
// toward +y (and a hair toward −x), which decides edges and vertices consistently. It needs
// edge functions that are exactly negated for the two triangles on an edge: computed from the
// canonical end, with EK_PRECISE so that no fused multiply-add changes one of them.

EK_CONST int EK_VOXELIZE_SUPERSAMPLE = 4;
EK_CONST int EK_VOXELIZE_WORD_BITS = 32;

// Bits of one fine column: fine samples along z, rounded up to whole words.
int voxelizeWordsPerColumn(int fineResolutionZ) {
    return (fineResolutionZ + EK_VOXELIZE_WORD_BITS - 1) / EK_VOXELIZE_WORD_BITS;
}

// A world position in fine-grid coordinates (fine sample (i, j, k) at (i + ½, j + ½, k + ½)).
vec3 voxelizeFineCoord(vec3 x, vec3 volumeMin, vec3 fineVoxelSize) {
    EK_PRECISE vec3 c = (x - volumeMin) / fineVoxelSize;
    return c;
}

// Twice the signed area of (u, v, p), computed from the canonical end of the edge u–v so that the
// two triangles sharing it get exactly opposite values.
float voxelizeEdgeFunction(vec2 u, vec2 v, vec2 p) {
    const bool swapped = u.x > v.x || (u.x == v.x && u.y > v.y);
    const vec2 s = swapped ? v : u;
    const vec2 e = swapped ? u : v;
    EK_PRECISE float w = (e.x - s.x) * (p.y - s.y) - (e.y - s.y) * (p.x - s.x);
    return swapped ? -w : w;
}

// Whether the sample p lies on the inside of edge u–v of a triangle whose third vertex is o:
// strictly on o's side, or on the edge with the triangle on the left of the canonical direction.
bool voxelizeInsideEdge(vec2 u, vec2 v, vec2 o, vec2 p, EK_OUT(float) weight) {
    const float wp = voxelizeEdgeFunction(u, v, p);
    const float wo = voxelizeEdgeFunction(u, v, o);
    const bool swapped = u.x > v.x || (u.x == v.x && u.y > v.y);
    // wo > 0 means o lies left of u → v; flip to the canonical direction's side.
    const bool leftOfCanonical = swapped ? wo < 0.0f : wo > 0.0f;
    weight = wo > 0.0f ? wp : -wp;  // ≥ 0 inside: the barycentric weight of o, times 2·area
    if (wp == 0.0f) return leftOfCanonical;
    return weight > 0.0f;
}

// If the column through fine-grid point (px, py) crosses triangle (a, b, c) (fine coordinates),
// returns true and the crossing's z. Triangles seen edge-on (zero projected area) never count:
// their neighbours' edges decide the columns along them.
bool voxelizeColumnCrossing(vec3 a, vec3 b, vec3 c, vec2 p, EK_OUT(float) z) {
    z = 0.0f;
    const vec2 a2 = vec2(a.x, a.y);
    const vec2 b2 = vec2(b.x, b.y);
    const vec2 c2 = vec2(c.x, c.y);
    if (voxelizeEdgeFunction(a2, b2, c2) == 0.0f) return false;
    float wc = 0.0f;
    float wa = 0.0f;
    float wb = 0.0f;
    if (!voxelizeInsideEdge(a2, b2, c2, p, wc)) return false;
    if (!voxelizeInsideEdge(b2, c2, a2, p, wa)) return false;
    if (!voxelizeInsideEdge(c2, a2, b2, p, wb)) return false;
    const float sum = wa + wb + wc;
    z = sum > 0.0f ? (wa * a.z + wb * b.z + wc * c.z) / sum : a.z;
    return true;
}

// The fine sample whose bit a crossing at fine z flips: the first with its centre strictly above
// z, clamped to 0 below the volume; `height` (the column's samples) means none. Written with
// comparisons that a NaN fails (clamp() of a NaN is a NaN, and int() of one is undefined: INT_MIN
// on x86, a write far outside the bits): a crossing whose z overflowed is placed at the bottom.
int voxelizeToggleIndex(float z, int height) {
    const float k = floor(z + 0.5f);
    if (!(k > 0.0f)) return 0;
    if (!(k < float(height))) return height;
    return int(k);
}

// Whether every coordinate of a fine-grid point is a number a float holds (no NaN, no infinity).
bool voxelizeFinite(vec3 c) {
    const float big = 3.4e38f;
    return abs(c.x) <= big && abs(c.y) <= big && abs(c.z) <= big;
}

// Step 1 for one triangle (world positions): flips one bit in every fine column it crosses.
void voxelizeTriangle(vec3 pa, vec3 pb, vec3 pc, vec3 volumeMin, vec3 fineVoxelSize,
                      ivec3 fineRes) {
    const vec3 a = voxelizeFineCoord(pa, volumeMin, fineVoxelSize);
    const vec3 b = voxelizeFineCoord(pb, volumeMin, fineVoxelSize);
    const vec3 c = voxelizeFineCoord(pc, volumeMin, fineVoxelSize);
    // A mesh far outside the volume in voxel units (radius 1e30 around a volume 1e-30 wide)
    // overflows to infinities here, and the column range below would be int() of a NaN. No
    // column can be told from another at that distance; the triangle is left out (the callers
    // refuse such meshes first: checkMeshFitsVoxelGrid in core/mesh_voxelize.h).
    if (!voxelizeFinite(a) || !voxelizeFinite(b) || !voxelizeFinite(c)) return;
    // Columns whose centres (i + ½, j + ½) lie in the projected bounding box.
    const vec2 lo = min(min(vec2(a.x, a.y), vec2(b.x, b.y)), vec2(c.x, c.y));
    const vec2 hi = max(max(vec2(a.x, a.y), vec2(b.x, b.y)), vec2(c.x, c.y));
    const int i0 = int(clamp(ceil(lo.x - 0.5f), 0.0f, float(fineRes.x)));
    const int i1 = int(clamp(floor(hi.x - 0.5f), -1.0f, float(fineRes.x - 1)));
    const int j0 = int(clamp(ceil(lo.y - 0.5f), 0.0f, float(fineRes.y)));
    const int j1 = int(clamp(floor(hi.y - 0.5f), -1.0f, float(fineRes.y - 1)));
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            float z = 0.0f;
            if (!voxelizeColumnCrossing(a, b, c, vec2(float(i) + 0.5f, float(j) + 0.5f), z))
                continue;
            const int k = voxelizeToggleIndex(z, fineRes.z);
            if (k < fineRes.z) toggleSample(j * fineRes.x + i, k);
        }
}

// Step 2 for one word of a column, lowest word first: bit b becomes the XOR of bits 0..b and of
// every earlier word (carry: all ones when an odd number of flips lie below).
uint voxelizePrefixXor(uint word, EK_INOUT(uint) carry) {
    uint x = word;
    x ^= x << 1u;
    x ^= x << 2u;
    x ^= x << 4u;
    x ^= x << 8u;
    x ^= x << 16u;
    x ^= carry;
    carry = (x >> 31u) != 0u ? 0xFFFFFFFFu : 0u;
    return x;
}

int voxelizeCountBits4(uint nibble) {
    return int(nibble & 1u) + int((nibble >> 1u) & 1u) + int((nibble >> 2u) & 1u) +
           int((nibble >> 3u) & 1u);
}

// Step 3: the fraction of voxel v's 64 samples inside (the 4 z-samples of a voxel share one word,
// since 4 divides 32).
float voxelizeCoverage(ivec3 v, ivec3 fineRes) {
    const int s = EK_VOXELIZE_SUPERSAMPLE;
    const int words = voxelizeWordsPerColumn(fineRes.z);
    const int k = v.z * s;
    const int word = k / EK_VOXELIZE_WORD_BITS;
    const uint shift = uint(k % EK_VOXELIZE_WORD_BITS);
    int inside = 0;
    for (int dy = 0; dy < s; ++dy)
        for (int dx = 0; dx < s; ++dx) {
            const int column = (v.y * s + dy) * fineRes.x + v.x * s + dx;
            inside += voxelizeCountBits4((fetchInsideWord(column * words + word) >> shift) & 15u);
        }
    return float(inside) / float(s * s * s);
}
