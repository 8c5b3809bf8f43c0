// Fresnel reflection where light crosses the sharp surface of a material (Ihrke et al. 2007 §3.1:
// the reflection factor r for unpolarized light, and the transmission factor t = 1 − r that
// scales what goes on), the same on the GPU and in the CPU twin. Functions only; needs
// sampling.h (params, sampleField) included before, and a kernel file's includer for the rest.
//
// A grid smears a sharp surface (glass, water) over a few voxels (a mesh's index is blurred by
// σ = 1.5 voxels). Through that layer n changes continuously, and the ray equation bends a ray as
// Snell's law does in a layered medium (n sin θ is conserved across the layers), but nothing in
// it reflects. So the crossing of a surface is found and, once crossed, the light that went
// through is scaled by 1 − R(n1, n2, θ):
//  - Only the index of materials marked `fresnel` (materialFresnel) finds surfaces: n_surface =
//    1 + their excess index. A GRIN lens or hot air changes n over many wavelengths and reflects
//    nothing, however steep its gradient is on the grid.
//  - A crossing is a run of steps along each of which n_surface changes by more than the caller's
//    threshold (a slope per voxel × the step's length in voxels). It starts with n1 = the total n
//    at the last flat point before it (see surfaceWalkStep), gathers the ∇n it meets (the surface's
//    normal, up to sign), and ends at the first step that changes n_surface less where |∇n| is
//    below the slope too (out of the layer: a ray turning inside it moves along it for a step),
//    with n2 = the total n there.
//  - The angles come from the ray's momentum v = n dx/ds there: across a layer whose ∇n is along
//    its normal N the tangential part |v − (v·N)N| = n sin θ is conserved exactly (Snell's law),
//    even where the sampled path lets |v| drift from n (wavefront.h) and would tilt a direction
//    taken from v/|v|. N is the direction of the ∇n gathered over the crossing (the ray has
//    already bent a little in the gradient's tail before n_surface shows the step).
//  - R(n1 → n2, θ1) = R(n2 → n1, θ2) (Stokes' reciprocity); it is taken on the side of the lower
//    index, where R changes slowest with the angle (entering glass near grazing, R goes from 0.39
//    to 1 over 80°-90° outside but over 41.0°-41.8° inside).
//  - A ray that turns back inside the smeared surface (total internal reflection) ends its
//    crossing at the n it started from: R(n, n) = 0, and all its light goes on, reflected.
// What becomes of the reflected part is the caller's: the wavefront counts it without following
// it (as the paper), view rays look along surfaceMirrorDirection (view_march.h).

// R for unpolarized light from index n1 into n2 at incidence cos θ1 = cosI (its sign ignored):
// the mean of the s and p reflectances (Born & Wolf), exact, not Schlick's approximation. 1 past
// the critical angle (total internal reflection) and at grazing incidence; 0 where n1 = n2.
float fresnelReflectance(float n1, float n2, float cosI) {
    if (n1 == n2) return 0.0f;  // exactly: a turned-back ray (n1 = n2) loses nothing
    const float c = min(abs(cosI), 1.0f);
    if (!(c > 0.0f)) return 1.0f;
    const float eta = n1 / n2;
    const float sin2T = eta * eta * (1.0f - c * c);
    if (sin2T >= 1.0f) return 1.0f;
    const float cosT = sqrt(1.0f - sin2T);
    const float rs = (n1 * c - n2 * cosT) / (n1 * c + n2 * cosT);
    const float rp = (n2 * c - n1 * cosT) / (n2 * c + n1 * cosT);
    return 0.5f * (rs * rs + rp * rp);
}

// 1 + the excess index of the materials whose edges are sharp surfaces, at volume-index point p.
float surfaceIndexAt(vec3 indexPos) {
    EK_PRECISE float n = 1.0f;
    for (int m = 0; m < materialCount(params); ++m) {
        if (!materialFresnel(params.materials[m])) continue;
        const float f = sampleField(materialSlot(params.materials[m]), indexPos);
        n += materialIndexExcess(f, materialIndexSlope(params.materials[m]),
                                 materialInverseAmbient(params.materials[m]));
    }
    return n;
}

// Whether any material has sharp surfaces: without one there is nothing to find.
bool anySurfaces() {
    for (int m = 0; m < materialCount(params); ++m)
        if (materialFresnel(params.materials[m])) return true;
    return false;
}

// What a ray carries across surfaces, at the start of a walk at a point of total index n and
// surface index nSurface: x: n_surface at the last point; y: the total n where the current
// crossing began, 0 outside a crossing; z: the total n at the last point where n_surface was
// flat (see surfaceWalkStep) or a crossing ended; w: 1 while a ray that starts on a surface (a
// reflected one, from where its crossing began) has not yet left that surface's layer, else 0.
vec4 surfaceWalkStart(float n, float nSurface) {
    return vec4(nSurface, 0.0f, n, 0.0f);
}

// The walk of a ray that starts in a surface's layer, going away from it: no crossing until it
// is out (else it would find a crossing of the layer's tail, from wherever in it it started).
vec4 surfaceWalkStartOnSurface(float n, float nSurface) {
    return vec4(nSurface, 0.0f, n, 1.0f);
}

// One step of that walk, to where ∇n (xyz) and n (w) are g, n_surface is nSurface and the ray's
// momentum is v (n dx/ds); `normal` (xyz) gathers the ∇n met in the crossing. minChange: the
// change of n_surface over this step above which it is crossing a surface; maxSlope: the |∇n|
// (per scene unit) below which a crossing may end. Returns the transmittance at this step: 1 − R
// where a crossing ends, else 1.
float surfaceWalkStep(EK_INOUT(vec4) walk, EK_INOUT(vec4) normal, vec4 g, float nSurface, vec3 v,
                      float minChange, float maxSlope) {
    const float change = abs(nSurface - walk.x);
    const bool steep = change > minChange;
    walk.x = nSurface;
    if (walk.w != 0.0f) {  // still leaving the surface it started on
        if (steep || length(vec3(g)) > maxSlope) return 1.0f;
        walk.w = 0.0f;
        walk.z = g.w;
        return 1.0f;
    }
    if (steep) {
        if (walk.y == 0.0f) {
            walk.y = walk.z;
            normal = vec4(0.0f);
        }
        normal += vec4(vec3(g), 0.0f);
        return 1.0f;
    }
    // A step in the tail of a surface's layer changes n_surface by less than minChange but more
    // than nothing: the n where the next crossing begins is taken where it is flat, n_surface not
    // changing or ∇n below maxSlope (as where a crossing ends), else a ray meeting the layer's
    // tail a step before its steep part would enter glass from n = 1.005 (measured: R(60°) 3e-3
    // low on view rays). Not changing alone is flat, so that n1 follows a graded medium (hot air)
    // around a glass.
    if (change == 0.0f || length(vec3(g)) <= maxSlope) walk.z = g.w;
    if (walk.y == 0.0f) return 1.0f;
    if (length(vec3(g)) > maxSlope) {  // still in the layer
        normal += vec4(vec3(g), 0.0f);
        return 1.0f;
    }
    const float n1 = walk.y;
    walk.y = 0.0f;
    walk.z = g.w;  // out of the layer: a crossing right after this one begins here
    const float nLow = min(n1, g.w);
    const float nHigh = max(n1, g.w);
    const float size = length(vec3(normal));
    const float along = size > 0.0f ? dot(v, vec3(normal) / size) : length(v);
    const float tangential2 = max(dot(v, v) - along * along, 0.0f);  // (n sin θ)²
    const float sin2Low = tangential2 / (nLow * nLow);
    if (sin2Low >= 1.0f) return 0.0f;  // grazing on the lower side: all reflected
    return 1.0f - fresnelReflectance(nLow, nHigh, sqrt(1.0f - sin2Low));
}

// The unit direction a ray that has just crossed a surface would have taken had it been reflected
// there: back on the side it came from (index n1), with the tangential part of its momentum v
// (conserved, as above) and the normal part reversed. normalSum: the ∇n gathered over the
// crossing (surfaceWalkStep's `normal`), whose direction is the surface's normal up to sign.
vec3 surfaceMirrorDirection(vec3 v, vec3 normalSum, float n1) {
    const float size = length(normalSum);
    if (!(size > 0.0f)) return -normalize(v);
    const vec3 normal = normalSum / size;
    const float along = dot(v, normal);
    const vec3 tangential = v - along * normal;
    const float across = sqrt(max(n1 * n1 - dot(tangential, tangential), 0.0f));
    return normalize(tangential - (along >= 0.0f ? across : -across) * normal);
}
