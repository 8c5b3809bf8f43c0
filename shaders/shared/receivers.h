// Receivers (core/scene.h ReceiverSpec): diffuse axis-aligned planes across the volume that photons
// and view rays stop on. The geometry both sides share, and the receiver map's layout. Needs
// optics.h and sampling.h (params, volumeVoxelSize).
//
// A receiver r is the plane x[axis] = position; its front half-space is facing·(x[axis] −
// position) > 0. A segment a → b hits it where that signed distance changes sign; it hits the
// front face when a lies in front. The map of a plane receiver covers the volume's extent along
// the axes u = (axis + 1) % 3 and w = (axis + 2) % 3 with receiverMapWidth × receiverMapHeight
// texels; texel (i, j) covers [i, i + 1) × [j, j + 1) in map coordinates, x fastest, from index
// receiverMapStart (the accessors of GpuReceiver, gpu_types.h).

float receiverSide(int r, vec3 x) {
    const GpuReceiver receiver = params.receivers[r];
    return receiverFacing(receiver) * (x[receiverAxis(receiver)] - receiverPosition(receiver));
}

// The first receiver the segment a → b reaches (smallest fraction t ∈ [0, 1] along it), or −1.
// front gets whether it reaches that receiver from its front side.
int receiverCrossing(vec3 a, vec3 b, EK_OUT(float) t, EK_OUT(bool) front) {
    int hit = -1;
    t = 2.0f;
    front = false;
    for (int r = 0; r < receiverCount(params); ++r) {
        const float sa = receiverSide(r, a);
        const float sb = receiverSide(r, b);
        if ((sa > 0.0f) == (sb > 0.0f)) continue;
        const float f = sa / (sa - sb);
        if (f < t) {
            t = f;
            hit = r;
            front = sa > 0.0f;
        }
    }
    t = clamp(t, 0.0f, 1.0f);
    return hit;
}

// The point a fraction t along a → b, placed exactly on receiver r's plane.
vec3 receiverHitPoint(int r, vec3 a, vec3 b, float t) {
    vec3 x = a + (b - a) * t;
    const GpuReceiver receiver = params.receivers[r];
    x[receiverAxis(receiver)] = receiverPosition(receiver);
    return x;
}

// The unit normal of receiver r's front face.
vec3 receiverNormal(int r) {
    const GpuReceiver receiver = params.receivers[r];
    vec3 n = vec3(0.0f);
    n[receiverAxis(receiver)] = receiverFacing(receiver);
    return n;
}

// The continuous map coordinates of world point x on receiver r's map, texel centres at half
// integers.
vec2 receiverMapCoord(int r, vec3 x) {
    const GpuReceiver receiver = params.receivers[r];
    const int axis = receiverAxis(receiver);
    const int u = (axis + 1) % 3;
    const int w = (axis + 2) % 3;
    return vec2((x[u] - params.volumeMin[u]) / (params.volumeMax[u] - params.volumeMin[u]) *
                    float(receiverMapWidth(receiver)),
                (x[w] - params.volumeMin[w]) / (params.volumeMax[w] - params.volumeMin[w]) *
                    float(receiverMapHeight(receiver)));
}

// The four texels around map coordinate q (bilinear, texel centres at half integers, clamped to
// the map's edge) as indices into the receiver map, and their weights.
void receiverBilinear(int r, vec2 q, EK_OUT(ivec4) index, EK_OUT(vec4) weight) {
    const GpuReceiver receiver = params.receivers[r];
    const int width = receiverMapWidth(receiver);
    const int height = receiverMapHeight(receiver);
    const int start = receiverMapStart(receiver);
    const vec2 p = q - vec2(0.5f);
    const vec2 base = floor(p);
    const vec2 f = p - base;
    const ivec2 i0 = clamp(ivec2(base), ivec2(0), ivec2(width - 1, height - 1));
    const ivec2 i1 = clamp(ivec2(base) + ivec2(1), ivec2(0), ivec2(width - 1, height - 1));
    index = ivec4(start + i0.y * width + i0.x, start + i0.y * width + i1.x,
                  start + i1.y * width + i0.x, start + i1.y * width + i1.x);
    weight = vec4((1.0f - f.x) * (1.0f - f.y), f.x * (1.0f - f.y), (1.0f - f.x) * f.y, f.x * f.y);
}

// The area of one texel of receiver r's map, in scene units².
float receiverTexelArea(int r) {
    const GpuReceiver receiver = params.receivers[r];
    const int axis = receiverAxis(receiver);
    const int u = (axis + 1) % 3;
    const int w = (axis + 2) % 3;
    return (params.volumeMax[u] - params.volumeMin[u]) / float(receiverMapWidth(receiver)) *
           ((params.volumeMax[w] - params.volumeMin[w]) / float(receiverMapHeight(receiver)));
}
