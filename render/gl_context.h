#pragma once
// OpenGL 4.3 core contexts: headless through EGL (rendering, tests, CI on Mesa llvmpipe) and a
// GLFW window for the interactive viewer. Function loading goes through libepoxy, so callers in
// render/ include <epoxy/gl.h> and call GL directly once a context is current; apps/ includes no
// GL header (scripts/check-layering.sh) and goes through render/ instead.
//
// Every failure (no EGL, no display, driver below 4.3, missing extension) is an eikon::Error with
// a reason that says what was found and what to install, never a crash: machines without GL 4.3
// fall back to the CPU twin, and that decision needs a catchable error.
#include <array>
#include <cstdint>
#include <memory>
#include <string>

struct GLFWwindow;

namespace eikon {

// Driver limits the pipeline sizes its dispatches and volumes against.
struct GlLimits {
    std::array<int, 3> maxComputeWorkGroupCount{};
    std::array<int, 3> maxComputeWorkGroupSize{};
    int maxComputeWorkGroupInvocations = 0;
    int maxComputeSharedMemorySize = 0;  // bytes
    int max3DTextureSize = 0;            // texels per side
    int maxImageUnits = 0;
    int maxShaderStorageBufferBindings = 0;
    std::int64_t maxShaderStorageBlockSize = 0;  // bytes
    int timerQueryBits = 0;  // GL_QUERY_COUNTER_BITS of GL_TIME_ELAPSED; 0: no GPU timing
};

class GlContext {
public:
    virtual ~GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // Binds the context to the calling thread; GL calls go to it afterwards.
    virtual void makeCurrent() = 0;
    // Unbinds it from the calling thread. A thread cannot have a GLX (window) and an EGL
    // (headless) context current at once: release one before making the other current.
    virtual void releaseCurrent() = 0;

    // Queried once at creation, so they stay readable whichever context is current.
    const std::string& rendererName() const { return renderer_; }
    const std::string& vendorName() const { return vendor_; }
    const std::string& versionString() const { return version_; }
    int majorVersion() const { return major_; }
    int minorVersion() const { return minor_; }
    const GlLimits& limits() const { return limits_; }
    // True when GL_KHR_debug messages are routed to logWarning (debug builds, EIKON_GL_DEBUG=1).
    bool debugOutput() const { return debugOutput_; }

    // Waits until the GPU has finished every command issued so far (glFinish), so that a
    // wall-clock time includes the work; the context must be current.
    void finish() const;

protected:
    GlContext() = default;
    // Called by subclasses with the new context current: checks GL >= 4.3 with compute shaders
    // (throws Error(where, ...) otherwise), reads strings and limits, installs the debug hook.
    void initialize(const std::string& where);

private:
    std::string renderer_;
    std::string vendor_;
    std::string version_;
    int major_ = 0;
    int minor_ = 0;
    GlLimits limits_;
    bool debugOutput_ = false;
};

// Whether a renderer name is a software rasterizer (Mesa llvmpipe, softpipe, swrast): GPU work
// then runs on the CPU inside the GL calls, and the CPU twin of a stage is usually faster.
bool isSoftwareRenderer(const std::string& rendererName);

// Whether GL debug output is wanted: debug builds, the environment sets EIKON_GL_DEBUG=1, or the
// program asked (setGlDebugRequested: the command line's --gl-debug).
bool glDebugRequested();
// Asks for GL debug output (GL_KHR_debug messages as warnings) in contexts created from now on,
// whatever the build and the environment.
void setGlDebugRequested(bool requested);

// A 4.3 core context with no surface, current on the calling thread when this returns. Tries
// Mesa's surfaceless platform, then EGL devices (NVIDIA and other real drivers), then the default
// display. Throws eikon::Error("OpenGL", reason) if none gives a 4.3 core context.
std::unique_ptr<GlContext> createHeadlessContext();

// A GLFW window with a 4.3 core context, current on the calling thread after construction.
// Throws eikon::Error("OpenGL window", reason), e.g. when there is no display.
class GlfwWindowContext : public GlContext {
public:
    struct Size {
        int width = 0;
        int height = 0;
    };

    GlfwWindowContext(int width, int height, const std::string& title, bool visible = true);
    ~GlfwWindowContext() override;

    void makeCurrent() override;
    void releaseCurrent() override;
    void swapBuffers();
    bool shouldClose() const;
    void pollEvents();
    Size framebufferSize() const;
    // For input callbacks in the viewer; owned by this object.
    GLFWwindow* window() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace eikon
