// Macro layer that lets the files in shaders/shared/ compile both as GLSL 4.30 and as C++17 with
// GLM (the approach of NanoVDB's PNanoVDB.h). Rules for shared code:
//  - float literals carry an f suffix (GLM will not mix double and float);
//  - no swizzles (write vec3(v), v.x); only vec4/ivec4/uvec4 and scalars inside shared structs,
//    so std430 and C++ offsets agree without padding rules (a test checks them);
//  - out/inout parameters through EK_OUT(T)/EK_INOUT(T);
//  - constants through EK_CONST (a #define-free `const` in GLSL, `static constexpr` in C++);
//  - EK_PRECISE (GLSL `precise`) on results that must round as written on both sides: GLSL
//    compilers may fuse a·b − c·d into an fma or reassociate sums, C++ (no -mfma) does not.
//  - EK_FORCE_INLINE on a hot function the C++ compiler stopped inlining once its caller grew
//    (accumulateStep into the view's ray loop: 13 % of the view pass); nothing in GLSL.
// Kernel files (view_march.h) hold only functions: C++ includes them inside a struct body so
// that the shader's globals (params, fetchVoxel) become members; GLSL includes them at file scope.
#ifndef EIKON_SHARED_PLATFORM_H
#define EIKON_SHARED_PLATFORM_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define EK_OUT(T) T&
#define EK_INOUT(T) T&
#define EK_CONST static constexpr
#define EK_PRECISE
#define EK_FORCE_INLINE [[gnu::always_inline]]
#define EK_NAMESPACE_BEGIN \
    namespace eikon {      \
    namespace shared {     \
    using namespace glm;
#define EK_NAMESPACE_END \
    }                    \
    }
#else
#define EK_OUT(T) out T
#define EK_INOUT(T) inout T
#define EK_CONST const
#define EK_PRECISE precise
#define EK_FORCE_INLINE
#define EK_NAMESPACE_BEGIN
#define EK_NAMESPACE_END
#endif

#endif
