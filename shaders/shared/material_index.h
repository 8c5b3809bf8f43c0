// The refractive index one material adds to vacuum's n = 1 at a point where its field is f
// (core/scene.h MaterialSpec), the same in the shaders (shared/refraction.h) and on the host
// (core/resample.cpp checks n with it). Include at file scope, before refraction.h.
//
// - An ordinary material adds f·(ior − 1): linear in its field.
// - Gladstone–Dale hot air (inverseAmbient = 1/T_ambient > 0): f is the temperature excess
//   T − T_ambient in kelvin, and n − 1 of air is GD·T_ambient/T at constant pressure. Taken
//   relative to the ambient air (n = 1 there), n = 1 + GD·(T_ambient/(T_ambient + f) − 1)
//   = 1 − GD·f/(T_ambient + f). With iorMinusOne = −GD/T_ambient (the slope at f = 0, what the
//   parser stores as ior − 1) that is f·(ior − 1)/(1 + f/T_ambient): exact, not linearised
//   (the linear form was off by the factor 1 + f/T_ambient, 2x at T = 2·T_ambient).
//   f must stay above −T_ambient (absolute zero); resample.cpp rejects fields that do not.
#ifndef EIKON_SHARED_MATERIAL_INDEX_H
#define EIKON_SHARED_MATERIAL_INDEX_H
#include "platform.h"

// EK_PRECISE (platform.h) keeps the GLSL compiler from fusing or reassociating these products and
// sums (Mesa turned f·(ior − 1) + n into an fma, 1 ulp off the CPU twin).
#ifdef __cplusplus
#define EK_INLINE inline
#else
#define EK_INLINE
#endif

EK_NAMESPACE_BEGIN

EK_INLINE float materialIndexExcess(float f, float iorMinusOne, float inverseAmbient) {
    EK_PRECISE float excess = f * iorMinusOne;
    if (inverseAmbient != 0.0f) excess = excess / (1.0f + f * inverseAmbient);
    return excess;
}

EK_NAMESPACE_END

#endif
