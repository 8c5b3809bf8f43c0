// Specular highlights of the lights on sharp surfaces (Magnus's thesis §4.3, eqs. 4.9-4.12): the
// Cook–Torrance microfacet BRDF with the Trowbridge–Reitz (GGX) distribution D and the Schlick-GGX
// geometry term G of Unreal Engine 4 (Karis 2013: α = roughness², k = (roughness + 1)²/8), and
// the Fresnel term F for unpolarized light from the index on the viewer's side to the other at
// the halfway vector (fresnelReflectance, fresnel.h: exact, which the thesis's Cook–Torrance form
// of F is for a dielectric). The same on the GPU and the CPU twin; needs fresnel.h.
//
// The thesis takes F from the index of two neighbouring planes at every sample; here a sharp
// surface is a crossing of the smeared layer (fresnel.h's walk), and F takes the indices where
// the crossing began and ended, so the highlight does not depend on how many samples the layer
// spreads over.

// The radiance reflected toward unit v (pointing to the viewer) by a surface of unit normal
// `normal` (either sense) and `roughness` (0, 1] from light arriving from unit direction l
// (pointing to the light) with irradiance 1 on a plane facing it: f_r (n·l) = D F G / (4 n·v).
// n1: the index on the viewer's (and the light's) side, n2 across. 0 where the light is behind
// the surface or the viewer grazes it.
float ggxSpecular(vec3 normal, vec3 v, vec3 l, float roughness, float n1, float n2) {
    float nv = dot(normal, v);
    const vec3 n = nv < 0.0f ? -normal : normal;
    nv = abs(nv);
    const float nl = dot(n, l);
    if (!(nl > 0.0f) || !(nv > 0.0f)) return 0.0f;
    const vec3 h = normalize(v + l);
    const float nh = max(dot(n, h), 0.0f);
    const float alpha = roughness * roughness;
    const float alpha2 = alpha * alpha;
    // (n·h)²(α² − 1) + 1 as (n·h)² α² + sin² of the angle between them, the sine from a cross
    // product: near the lobe's peak 1 − (n·h)² loses every digit a small α needs (a float n·h
    // short of 1 by its last bit made the peak 1.5e-4 low at roughness 0.2).
    const vec3 across = cross(n, h);
    const float d = nh * nh * alpha2 + dot(across, across);
    const float distribution = alpha2 / (EK_PI * d * d);
    const float k = (roughness + 1.0f) * (roughness + 1.0f) / 8.0f;
    const float geometry = nl / (nl * (1.0f - k) + k) * (nv / (nv * (1.0f - k) + k));
    const float fresnel = fresnelReflectance(n1, n2, dot(v, h));
    return distribution * fresnel * geometry / (4.0f * nv);
}
