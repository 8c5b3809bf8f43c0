// shaders/shared/gpu_types.h compiles as C++ and as GLSL; this asks the GL driver for the std430
// offset, type and size of every member and compares them with offsetof and sizeof in C++.
#include <epoxy/gl.h>
#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "render/gl_context.h"
#include "render/shader_program.h"
#include "render/transport/wavefront/wavefront_tracing.h"  // GpuPhoton, GpuWavefrontPatch
#include "shaders/shared/gpu_types.h"

namespace {

using eikon::shared::GpuLight;
using eikon::shared::GpuMaterial;
using eikon::shared::GpuPhoton;
using eikon::shared::GpuReceiver;
using eikon::shared::GpuViewParams;
using eikon::shared::GpuWavefrontPatch;

// The rules the shared header promises: 16-byte members only, so C++ needs no padding rules.
static_assert(sizeof(glm::vec4) == 16 && sizeof(glm::ivec4) == 16, "GLM vectors are packed");
static_assert(std::is_standard_layout<GpuViewParams>::value, "offsetof needs standard layout");
static_assert(std::is_trivially_copyable<GpuViewParams>::value, "uploaded with memcpy");
static_assert(sizeof(GpuMaterial) % 16 == 0 && sizeof(GpuLight) % 16 == 0 &&
                  sizeof(GpuReceiver) % 16 == 0,
              "std430 rounds a struct's array stride up to its 16-byte alignment; C++ must agree");
static_assert(sizeof(GpuViewParams) % 16 == 0, "std430 rounds a block's size the same way");
static_assert(offsetof(GpuViewParams, materials) % 16 == 0 &&
                  offsetof(GpuViewParams, lights) % 16 == 0 &&
                  offsetof(GpuViewParams, receivers) % 16 == 0,
              "struct arrays start 16-byte aligned in std430");
static_assert(sizeof(GpuViewParams) ==
                  offsetof(GpuViewParams, particleColorIntegrals) +
                      EK_MAX_MATERIALS * EK_PARTICLE_COLOR_TABLE * sizeof(glm::vec4),
              "GpuViewParams ends with particleColorIntegrals[]: no trailing padding");

template <typename T>
struct GlType;
template <>
struct GlType<glm::vec4> {
    static constexpr GLenum value = GL_FLOAT_VEC4;
};
template <>
struct GlType<glm::ivec4> {
    static constexpr GLenum value = GL_INT_VEC4;
};
template <>
struct GlType<glm::uvec4> {
    static constexpr GLenum value = GL_UNSIGNED_INT_VEC4;
};
template <>
struct GlType<float> {
    static constexpr GLenum value = GL_FLOAT;
};
template <>
struct GlType<std::int32_t> {
    static constexpr GLenum value = GL_INT;
};
template <>
struct GlType<std::uint32_t> {
    static constexpr GLenum value = GL_UNSIGNED_INT;
};

struct Member {
    size_t offset;
    GLenum type;
};

// Buffer-variable name (as Mesa reports it: "<block member path>", no block name, since the
// block has no instance name) -> what C++ says.
using Layout = std::map<std::string, Member>;

#define EK_MEMBER(Struct, field)                                            \
    {                                                                       \
#field, {                                                           \
            offsetof(Struct, field), GlType<decltype(Struct::field)>::value \
        }                                                                   \
    }

Layout materialLayout() {
    return {EK_MEMBER(GpuMaterial, absorption), EK_MEMBER(GpuMaterial, scattering),
            EK_MEMBER(GpuMaterial, emission), EK_MEMBER(GpuMaterial, slot),
            EK_MEMBER(GpuMaterial, surface)};
}

Layout lightLayout() {
    return {EK_MEMBER(GpuLight, position), EK_MEMBER(GpuLight, direction),
            EK_MEMBER(GpuLight, radiance)};
}

Layout receiverLayout() {
    return {EK_MEMBER(GpuReceiver, plane), EK_MEMBER(GpuReceiver, albedo),
            EK_MEMBER(GpuReceiver, texels)};
}

// Adds `inner` under "<prefix>[i].", i < count, at `base + i * stride`.
void addArray(Layout& layout, const std::string& prefix, size_t base, size_t stride, int count,
              const Layout& inner) {
    for (int i = 0; i < count; ++i) {
        for (const auto& [name, member] : inner) {
            layout[prefix + "[" + std::to_string(i) + "]." + name] = {
                base + i * stride + member.offset, member.type};
        }
    }
}

Layout viewParamsLayout() {
    Layout fields = {
        EK_MEMBER(GpuViewParams, cameraOrigin),       EK_MEMBER(GpuViewParams, cameraRight),
        EK_MEMBER(GpuViewParams, cameraUp),           EK_MEMBER(GpuViewParams, cameraForward),
        EK_MEMBER(GpuViewParams, volumeMin),          EK_MEMBER(GpuViewParams, volumeMax),
        EK_MEMBER(GpuViewParams, resolution),         EK_MEMBER(GpuViewParams, image),
        EK_MEMBER(GpuViewParams, background),         EK_MEMBER(GpuViewParams, pipeline),
        EK_MEMBER(GpuViewParams, environment),        EK_MEMBER(GpuViewParams, environmentSky),
        EK_MEMBER(GpuViewParams, environmentHorizon), EK_MEMBER(GpuViewParams, environmentGround)};
    // An array of a basic type is one variable, named by its first element.
    fields["clipPlanes[0]"] = {offsetof(GpuViewParams, clipPlanes), GL_FLOAT_VEC4};
    fields["particleColorRanges[0]"] = {offsetof(GpuViewParams, particleColorRanges),
                                        GL_FLOAT_VEC4};
    fields["particleColors[0]"] = {offsetof(GpuViewParams, particleColors), GL_FLOAT_VEC4};
    fields["particleColorIntegrals[0]"] = {offsetof(GpuViewParams, particleColorIntegrals),
                                           GL_FLOAT_VEC4};
    addArray(fields, "materials", offsetof(GpuViewParams, materials), sizeof(GpuMaterial),
             EK_MAX_MATERIALS, materialLayout());
    addArray(fields, "lights", offsetof(GpuViewParams, lights), sizeof(GpuLight), EK_MAX_LIGHTS,
             lightLayout());
    addArray(fields, "receivers", offsetof(GpuViewParams, receivers), sizeof(GpuReceiver),
             EK_MAX_RECEIVERS, receiverLayout());
    Layout layout;
    for (const auto& [name, member] : fields) layout["params." + name] = member;
    return layout;
}

struct DriverVariable {
    GLint offset;
    GLenum type;
    GLint topLevelArrayStride;
    GLint blockIndex;
};

// Every buffer variable the driver reports, by name.
std::map<std::string, DriverVariable> driverVariables(GLuint program) {
    GLint count = 0;
    GLint maxName = 0;
    glGetProgramInterfaceiv(program, GL_BUFFER_VARIABLE, GL_ACTIVE_RESOURCES, &count);
    glGetProgramInterfaceiv(program, GL_BUFFER_VARIABLE, GL_MAX_NAME_LENGTH, &maxName);
    std::map<std::string, DriverVariable> variables;
    const GLenum props[] = {GL_OFFSET, GL_TYPE, GL_TOP_LEVEL_ARRAY_STRIDE, GL_BLOCK_INDEX};
    for (GLint i = 0; i < count; ++i) {
        std::string name(static_cast<size_t>(maxName), '\0');
        GLsizei length = 0;
        glGetProgramResourceName(program, GL_BUFFER_VARIABLE, i, maxName, &length, name.data());
        name.resize(static_cast<size_t>(length));
        GLint values[4] = {};
        glGetProgramResourceiv(program, GL_BUFFER_VARIABLE, i, 4, props, 4, nullptr, values);
        variables[name] = {values[0], static_cast<GLenum>(values[1]), values[2], values[3]};
    }
    return variables;
}

GLint blockIndex(GLuint program, const char* block) {
    return static_cast<GLint>(glGetProgramResourceIndex(program, GL_SHADER_STORAGE_BLOCK, block));
}

GLint blockDataSize(GLuint program, const char* block) {
    const GLenum prop = GL_BUFFER_DATA_SIZE;
    GLint size = -1;
    glGetProgramResourceiv(program, GL_SHADER_STORAGE_BLOCK,
                           static_cast<GLuint>(blockIndex(program, block)), 1, &prop, 1, nullptr,
                           &size);
    return size;
}

// Checks that the driver's variables of one block are exactly `expected`, with equal offsets
// and types. A member added to gpu_types.h but not listed here fails, by name.
void compareBlock(const std::map<std::string, DriverVariable>& driver, GLint block,
                  const Layout& expected) {
    size_t compared = 0;
    for (const auto& [name, variable] : driver) {
        if (variable.blockIndex != block) continue;
        INFO("driver reports " << name);
        const auto it = expected.find(name);
        REQUIRE(it != expected.end());
        CHECK(static_cast<size_t>(variable.offset) == it->second.offset);
        CHECK(variable.type == it->second.type);
        ++compared;
    }
    CHECK(compared == expected.size());
}

}  // namespace

TEST_CASE("std430 offsets of GpuViewParams agree between GLSL and C++", "[std430][gl]") {
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    const eikon::ShaderProgram program =
        eikon::ShaderProgram::compute("test/std430_view_params.comp");
    const std::map<std::string, DriverVariable> driver = driverVariables(program.id());
    REQUIRE_FALSE(driver.empty());

    const GLint viewBlock = blockIndex(program.id(), "B");
    REQUIRE(viewBlock != static_cast<GLint>(GL_INVALID_INDEX));
    const Layout expected = viewParamsLayout();
    compareBlock(driver, viewBlock, expected);
    CHECK(static_cast<size_t>(blockDataSize(program.id(), "B")) == sizeof(GpuViewParams));
    // params is not an array: no top-level stride.
    CHECK(driver.at("params.lights[1].radiance").topLevelArrayStride == 0);
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("std430 array strides of GpuMaterial and GpuLight equal their C++ sizes",
          "[std430][gl]") {
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    const eikon::ShaderProgram program =
        eikon::ShaderProgram::compute("test/std430_view_params.comp");
    const std::map<std::string, DriverVariable> driver = driverVariables(program.id());

    Layout materials;
    addArray(materials, "materialList", 0, 0, 1, materialLayout());
    compareBlock(driver, blockIndex(program.id(), "M"), materials);
    CHECK(driver.at("materialList[0].emission").topLevelArrayStride ==
          static_cast<GLint>(sizeof(GpuMaterial)));

    Layout lights;
    addArray(lights, "lightList", 0, 0, 1, lightLayout());
    compareBlock(driver, blockIndex(program.id(), "L"), lights);
    CHECK(driver.at("lightList[0].radiance").topLevelArrayStride ==
          static_cast<GLint>(sizeof(GpuLight)));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE(
    "std430 layouts of the particle structs GpuPhoton, GpuWavefrontPatch and GpuWavefrontEntry "
    "equal C++",
    "[std430][gl]") {
    static_assert(std::is_standard_layout<GpuWavefrontPatch>::value &&
                      std::is_trivially_copyable<GpuWavefrontPatch>::value,
                  "offsetof and memcpy");
    static_assert(sizeof(GpuPhoton) % 16 == 0 && sizeof(GpuWavefrontPatch) % 16 == 0,
                  "array strides are multiples of 16 bytes");
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    const eikon::ShaderProgram program =
        eikon::ShaderProgram::compute("test/std430_particles.comp");
    const std::map<std::string, DriverVariable> driver = driverVariables(program.id());

    Layout photon = {EK_MEMBER(GpuPhoton, position), EK_MEMBER(GpuPhoton, direction),
                     EK_MEMBER(GpuPhoton, flux)};
    Layout photons;
    addArray(photons, "photonList", 0, 0, 1, photon);
    compareBlock(driver, blockIndex(program.id(), "P"), photons);
    CHECK(driver.at("photonList[0].flux").topLevelArrayStride ==
          static_cast<GLint>(sizeof(GpuPhoton)));

    // Arrays of vec4 inside the struct: the driver reports each as its first element, "[0]".
    Layout patch = {{"corner[0]", {offsetof(GpuWavefrontPatch, corner), GL_FLOAT_VEC4}},
                    {"velocity[0]", {offsetof(GpuWavefrontPatch, velocity), GL_FLOAT_VEC4}},
                    EK_MEMBER(GpuWavefrontPatch, power),
                    EK_MEMBER(GpuWavefrontPatch, state),
                    EK_MEMBER(GpuWavefrontPatch, surface),
                    EK_MEMBER(GpuWavefrontPatch, surfaceNormal)};
    Layout patches;
    addArray(patches, "patchList", 0, 0, 1, patch);
    compareBlock(driver, blockIndex(program.id(), "W"), patches);
    CHECK(driver.at("patchList[0].surfaceNormal").topLevelArrayStride ==
          static_cast<GLint>(sizeof(GpuWavefrontPatch)));

    // The round lists' entries: a patch, then its tally (the members the shader touches).
    using eikon::shared::GpuWavefrontEntry;
    using eikon::shared::GpuWavefrontTally;
    const auto at = [](size_t tallyMember) {
        return static_cast<GLint>(offsetof(GpuWavefrontEntry, tally) + tallyMember);
    };
    CHECK(driver.at("entryList[0].piece.power").offset ==
          static_cast<GLint>(offsetof(GpuWavefrontEntry, piece) +
                             offsetof(GpuWavefrontPatch, power)));
    CHECK(driver.at("entryList[0].tally.lost").offset == at(offsetof(GpuWavefrontTally, lost)));
    CHECK(driver.at("entryList[0].tally.reflected").offset ==
          at(offsetof(GpuWavefrontTally, reflected)));
    CHECK(driver.at("entryList[0].tally.root").offset == at(offsetof(GpuWavefrontTally, root)));
    CHECK(driver.at("entryList[0].tally.root").topLevelArrayStride ==
          static_cast<GLint>(sizeof(GpuWavefrontEntry)));
    CHECK(glGetError() == GL_NO_ERROR);
}
