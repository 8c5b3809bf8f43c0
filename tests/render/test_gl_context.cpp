// Headless OpenGL: context creation, a compute dispatch read back, debug output, stage timing.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/log.h"
#include "render/gl_context.h"
#include "render/gpu_timer.h"
#include "render/shader_program.h"

namespace {

// Sets an environment variable for one test and puts the old value back.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        const char* old = std::getenv(name);
        hadOld_ = old != nullptr;
        if (hadOld_) old_ = old;
        setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (hadOld_) {
            setenv(name_.c_str(), old_.c_str(), 1);
        } else {
            unsetenv(name_.c_str());
        }
    }

private:
    std::string name_;
    std::string old_;
    bool hadOld_ = false;
};

std::vector<unsigned> runGidDouble(unsigned count) {
    eikon::ShaderProgram program = eikon::ShaderProgram::compute("test/gid_double.comp");
    const std::vector<unsigned> poison(count, 0xdeadbeefu);
    GLuint buffer = 0;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, count * sizeof(unsigned), poison.data(), GL_STATIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
    program.use();
    program.setUint("count", count);
    const unsigned groupSize = static_cast<unsigned>(program.localSize()[0]);
    glDispatchCompute((count + groupSize - 1) / groupSize, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<unsigned> result(count);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, count * sizeof(unsigned), result.data());
    glDeleteBuffers(1, &buffer);
    return result;
}

}  // namespace

TEST_CASE("a headless context gives OpenGL 4.3 core or newer", "[gl]") {
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    REQUIRE(context);
    INFO("GL " << context->versionString() << " on " << context->rendererName());
    CHECK(context->majorVersion() * 10 + context->minorVersion() >= 43);
    CHECK_FALSE(context->rendererName().empty());
    CHECK_FALSE(context->vendorName().empty());

    // The minimums GL 4.3 guarantees; a smaller number means the limits were read wrongly.
    const eikon::GlLimits& limits = context->limits();
    CHECK(limits.maxComputeWorkGroupCount[0] >= 65535);
    CHECK(limits.maxComputeWorkGroupCount[2] >= 65535);
    CHECK(limits.maxComputeWorkGroupSize[0] >= 1024);
    CHECK(limits.maxComputeWorkGroupSize[2] >= 64);
    CHECK(limits.maxComputeWorkGroupInvocations >= 1024);
    CHECK(limits.maxComputeSharedMemorySize >= 32768);
    CHECK(limits.max3DTextureSize >= 2048);
    CHECK(limits.maxImageUnits >= 8);
    CHECK(limits.maxShaderStorageBufferBindings >= 8);
    CHECK(limits.maxShaderStorageBlockSize >= (1 << 24));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("a compute shader writes 2 gid + 1 into an SSBO of 1000 uints", "[gl]") {
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    const unsigned count = 1000;  // not a multiple of the local size 64: the tail group is partial
    const std::vector<unsigned> result = runGidDouble(count);
    CHECK(glGetError() == GL_NO_ERROR);
    std::vector<unsigned> expected(count);
    for (unsigned i = 0; i < count; ++i) expected[i] = 2 * i + 1;
    CHECK(result == expected);
}

TEST_CASE("headless contexts share a display and survive each other", "[gl]") {
    std::unique_ptr<eikon::GlContext> first = eikon::createHeadlessContext();
    {
        std::unique_ptr<eikon::GlContext> second = eikon::createHeadlessContext();
        CHECK(second->rendererName() == first->rendererName());
    }
    // Destroying the second must not terminate the display under the first.
    REQUIRE_NOTHROW(first->makeCurrent());
    first->releaseCurrent();
    CHECK(eglGetCurrentContext() == EGL_NO_CONTEXT);
    REQUIRE_NOTHROW(first->makeCurrent());
    CHECK(runGidDouble(100)[99] == 199u);
}

TEST_CASE("EIKON_GL_DEBUG=1 routes GL debug messages to warnings", "[gl][debug]") {
    ScopedEnv debug("EIKON_GL_DEBUG", "1");
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    REQUIRE(context->debugOutput());
    eikon::ScopedWarningCapture capture;
    // Binding a name glGenBuffers never returned is GL_INVALID_OPERATION in a core context.
    glBindBuffer(GL_ARRAY_BUFFER, 987654u);
    CHECK(glGetError() == GL_INVALID_OPERATION);
    CHECK(capture.contains("OpenGL debug (api, error"));
}

TEST_CASE("a window without a display is an Error, not a crash", "[gl][window]") {
    if (std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY")) {
        WARN("a display is set; this test needs a machine without one");
        return;
    }
    try {
        eikon::GlfwWindowContext window(64, 64, "eikon test", false);
        FAIL("a window opened without a display");
    } catch (const eikon::Error& e) {
        INFO(e.what());
        CHECK(e.where() == "OpenGL window");
        CHECK_FALSE(e.reason().empty());
    }
}

TEST_CASE("stage timer: first-use order, repeats summed, GPU and CPU times", "[gl][timer]") {
    std::unique_ptr<eikon::GlContext> context = eikon::createHeadlessContext();
    eikon::GpuStageTimer timer;
    CHECK(timer.gpuTiming() == (context->limits().timerQueryBits > 0));
    timer.begin("upload");
    runGidDouble(1000);
    timer.end();
    timer.begin("march");
    runGidDouble(64);
    timer.end();
    timer.begin("upload");
    timer.end();

    CHECK_THROWS_AS(timer.end(), eikon::Error);
    timer.begin("smooth");
    CHECK_THROWS_WITH(timer.begin("view"), Catch::Contains("\"smooth\" is open"));
    timer.end();

    const std::vector<eikon::StageTime> times = timer.results();
    REQUIRE(times.size() == 3);
    CHECK(times[0].name == "upload");
    CHECK(times[0].calls == 2);
    CHECK(times[1].name == "march");
    CHECK(times[1].calls == 1);
    CHECK(times[2].name == "smooth");
    for (const eikon::StageTime& t : times) {
        CHECK(t.cpuMs >= 0.0);
        CHECK(t.gpuMs >= (timer.gpuTiming() ? 0.0 : -1.0));
    }
    CHECK(glGetError() == GL_NO_ERROR);

    timer.reset();
    CHECK(timer.results().empty());
}

TEST_CASE("a CPU-only stage timer reads GPU time as -1", "[gl][timer]") {
    // No context is needed: the CPU twin times its stages the same way.
    eikon::GpuStageTimer timer(false);
    CHECK_FALSE(timer.gpuTiming());
    timer.begin("march");
    timer.end();
    const std::vector<eikon::StageTime> times = timer.results();
    REQUIRE(times.size() == 1);
    CHECK(times[0].gpuMs == -1.0);
    CHECK(times[0].cpuMs >= 0.0);
}
