#include "render/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <dlfcn.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#include "core/error.h"
#include "core/log.h"

namespace eikon {
namespace {

const char* const kHeadlessWhere = "OpenGL";
const char* const kWindowWhere = "OpenGL window";
const char* const kMesaHint =
    "install libegl1 libegl-mesa0 libgl1-mesa-dri (Mesa's llvmpipe gives OpenGL 4.5 core on any "
    "CPU), or use a driver with OpenGL 4.3";

// ---- GL side, shared by both context kinds ---------------------------------------------------

const char* debugSourceName(GLenum source) {
    switch (source) {
        case GL_DEBUG_SOURCE_API:
            return "api";
        case GL_DEBUG_SOURCE_WINDOW_SYSTEM:
            return "window system";
        case GL_DEBUG_SOURCE_SHADER_COMPILER:
            return "shader compiler";
        case GL_DEBUG_SOURCE_THIRD_PARTY:
            return "third party";
        case GL_DEBUG_SOURCE_APPLICATION:
            return "application";
        default:
            return "other";
    }
}

const char* debugTypeName(GLenum type) {
    switch (type) {
        case GL_DEBUG_TYPE_ERROR:
            return "error";
        case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
            return "deprecated";
        case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
            return "undefined behaviour";
        case GL_DEBUG_TYPE_PORTABILITY:
            return "portability";
        case GL_DEBUG_TYPE_PERFORMANCE:
            return "performance";
        default:
            return "other";
    }
}

const char* debugSeverityName(GLenum severity) {
    switch (severity) {
        case GL_DEBUG_SEVERITY_HIGH:
            return "high";
        case GL_DEBUG_SEVERITY_MEDIUM:
            return "medium";
        case GL_DEBUG_SEVERITY_LOW:
            return "low";
        default:
            return "notification";
    }
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                               GLsizei length, const GLchar* message, const void* /*user*/) {
    // Called from inside the driver: an exception escaping here would cross C frames.
    try {
        std::string text(message, length >= 0 ? static_cast<size_t>(length) : std::strlen(message));
        logWarning(std::string("OpenGL debug (") + debugSourceName(source) + ", " +
                   debugTypeName(type) + ", " + debugSeverityName(severity) + ", id " +
                   std::to_string(id) + "): " + text);
    } catch (...) {
    }
}

void enableDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous, so that a message's stack trace points at the GL call that caused it.
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    // Notifications (buffer placement hints and the like) drown the real messages.
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr,
                          GL_FALSE);
    // Compile and link logs already reach the user through ShaderProgram's Error, with file
    // names and lines mapped back; the same log again here would only be noise.
    glDebugMessageControl(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr,
                          GL_FALSE);
}

std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

GlLimits queryLimits() {
    GlLimits limits;
    for (GLuint axis = 0; axis < 3; ++axis) {
        glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis,
                        &limits.maxComputeWorkGroupCount[axis]);
        glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, axis,
                        &limits.maxComputeWorkGroupSize[axis]);
    }
    glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &limits.maxComputeWorkGroupInvocations);
    glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &limits.maxComputeSharedMemorySize);
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &limits.max3DTextureSize);
    glGetIntegerv(GL_MAX_IMAGE_UNITS, &limits.maxImageUnits);
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &limits.maxShaderStorageBufferBindings);
    GLint64 blockSize = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockSize);
    limits.maxShaderStorageBlockSize = blockSize;
    glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &limits.timerQueryBits);
    return limits;
}

// ---- EGL -------------------------------------------------------------------------------------

const char* eglErrorName(EGLint error) {
    switch (error) {
        case EGL_SUCCESS:
            return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED:
            return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS:
            return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE:
            return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG:
            return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT:
            return "EGL_BAD_CONTEXT";
        case EGL_BAD_CURRENT_SURFACE:
            return "EGL_BAD_CURRENT_SURFACE";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_NATIVE_PIXMAP:
            return "EGL_BAD_NATIVE_PIXMAP";
        case EGL_BAD_NATIVE_WINDOW:
            return "EGL_BAD_NATIVE_WINDOW";
        case EGL_BAD_PARAMETER:
            return "EGL_BAD_PARAMETER";
        case EGL_BAD_SURFACE:
            return "EGL_BAD_SURFACE";
        case EGL_CONTEXT_LOST:
            return "EGL_CONTEXT_LOST";
        default:
            return "unknown EGL error";
    }
}

std::string lastEglError() {
    return eglErrorName(eglGetError());
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
        const bool startOk = p == list || p[-1] == ' ';
        const bool endOk = p[n] == '\0' || p[n] == ' ';
        if (startOk && endOk) return true;
    }
    return false;
}

// libepoxy dlopens the EGL and GL libraries on first use and aborts the process when one is
// missing; checking first turns that into an Error with an install hint.
void requireLibraries() {
    if (void* egl = dlopen("libEGL.so.1", RTLD_LAZY | RTLD_LOCAL)) {
        dlclose(egl);
    } else {
        throw Error(kHeadlessWhere,
                    std::string("cannot load libEGL.so.1 (") + dlerror() + "); " + kMesaHint);
    }
    for (const char* name : {"libOpenGL.so.0", "libGL.so.1"}) {
        if (void* gl = dlopen(name, RTLD_LAZY | RTLD_LOCAL)) {
            dlclose(gl);
            return;
        }
    }
    throw Error(kHeadlessWhere,
                "neither libOpenGL.so.0 nor libGL.so.1 can be loaded; install libopengl0 and "
                "libgl1-mesa-dri");
}

// EGL displays are per-process singletons and eglTerminate would invalidate every context on
// one, so two headless contexts on the same display count their uses and terminate at zero.
std::mutex& displayMutex() {
    static std::mutex m;
    return m;
}

std::map<EGLDisplay, int>& displayUses() {
    static std::map<EGLDisplay, int> uses;
    return uses;
}

bool acquireDisplay(EGLDisplay display, EGLint* major, EGLint* minor) {
    std::lock_guard<std::mutex> lock(displayMutex());
    if (!eglInitialize(display, major, minor)) return false;
    ++displayUses()[display];
    return true;
}

void releaseDisplay(EGLDisplay display) {
    std::lock_guard<std::mutex> lock(displayMutex());
    auto it = displayUses().find(display);
    if (it == displayUses().end() || --it->second > 0) return;
    displayUses().erase(it);
    eglTerminate(display);
}

class EglHeadlessContext final : public GlContext {
public:
    EglHeadlessContext(EGLDisplay display, EGLContext context)
        : display_(display), context_(context) {}

    ~EglHeadlessContext() override {
        releaseCurrent();
        eglDestroyContext(display_, context_);
        releaseDisplay(display_);
    }

    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw Error(kHeadlessWhere, "eglMakeCurrent failed (" + lastEglError() + ")");
    }

    void releaseCurrent() override {
        if (eglGetCurrentContext() == context_)
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }

    void finishSetup() { initialize(kHeadlessWhere); }

private:
    EGLDisplay display_;
    EGLContext context_;
};

// What a display gives without version attributes, to say what was found when 4.3 core fails.
std::string probeDefaultContext(EGLDisplay display, EGLConfig config) {
    const EGLint none[] = {EGL_NONE};
    EGLContext probe = eglCreateContext(display, config, EGL_NO_CONTEXT, none);
    if (probe == EGL_NO_CONTEXT) return "no OpenGL context at all (" + lastEglError() + ")";
    std::string found = "nothing";
    if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, probe)) {
        found = "\"" + glString(GL_VERSION) + "\" on \"" + glString(GL_RENDERER) + "\"";
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(display, probe);
    return "the driver offers " + found;
}

std::vector<EGLint> contextAttributes(bool khrCreateContext, bool debug) {
    std::vector<EGLint> attributes = {
        EGL_CONTEXT_MAJOR_VERSION_KHR,       4,
        EGL_CONTEXT_MINOR_VERSION_KHR,       3,
        EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR};
    if (debug) {
        // EGL 1.5 core spells the debug flag differently from EGL_KHR_create_context.
        if (khrCreateContext) {
            attributes.insert(attributes.end(),
                              {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR});
        } else {
            attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
        }
    }
    attributes.push_back(EGL_NONE);
    return attributes;
}

// Picks the config for a surfaceless context: none at all where the driver allows it.
bool chooseConfig(EGLDisplay display, const char* extensions, EGLConfig* config,
                  std::string& reason) {
    if (hasExtension(extensions, "EGL_KHR_no_config_context") ||
        hasExtension(extensions, "EGL_MESA_configless_context")) {
        *config = EGL_NO_CONFIG_KHR;
        return true;
    }
    // Surface type 0 matches every config: the context never gets a surface.
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, wanted, config, 1, &count) || count < 1) {
        reason = "no EGL config renders desktop OpenGL (" + lastEglError() + ")";
        return false;
    }
    return true;
}

// Checks what a display offers before asking it for a context; empty when all is there.
std::string missingDisplayFeatures(EGLDisplay display, EGLint major, EGLint minor) {
    const std::string version = std::to_string(major) + "." + std::to_string(minor);
    if (major == 1 && minor < 4) return "EGL " + version + " is older than 1.4 (no desktop GL)";
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context"))
        return "EGL " + version + " lacks EGL_KHR_surfaceless_context";
    const bool egl15 = major > 1 || minor >= 5;
    if (!egl15 && !hasExtension(extensions, "EGL_KHR_create_context"))
        return "EGL " + version + " lacks EGL_KHR_create_context (cannot ask for 4.3 core)";
    if (!hasExtension(eglQueryString(display, EGL_CLIENT_APIS), "OpenGL"))
        return "the display offers no desktop OpenGL (client APIs: " +
               std::string(eglQueryString(display, EGL_CLIENT_APIS)) + ")";
    return "";
}

// Creates and binds a 4.3 core context on an initialized display; null with a reason otherwise.
std::unique_ptr<EglHeadlessContext> createOnDisplay(EGLDisplay display, std::string& reason) {
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!eglBindAPI(EGL_OPENGL_API)) {
        reason = "eglBindAPI(EGL_OPENGL_API) failed (" + lastEglError() + ")";
        return nullptr;
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!chooseConfig(display, extensions, &config, reason)) return nullptr;
    const std::vector<EGLint> attributes =
        contextAttributes(hasExtension(extensions, "EGL_KHR_create_context"), glDebugRequested());
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes.data());
    if (context == EGL_NO_CONTEXT) {
        const std::string error = lastEglError();
        reason = "no OpenGL 4.3 core context (eglCreateContext: " + error + "); " +
                 probeDefaultContext(display, config);
        return nullptr;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        const EGLint error = eglGetError();
        reason =
            std::string("eglMakeCurrent without a surface failed (") + eglErrorName(error) + ")";
        if (error == EGL_BAD_ACCESS)
            reason += "; is a window's (GLX) context current on this thread? releaseCurrent() it";
        eglDestroyContext(display, context);
        return nullptr;
    }
    return std::make_unique<EglHeadlessContext>(display, context);
}

// Tries one display end to end; on failure leaves nothing behind and says why.
std::unique_ptr<GlContext> tryDisplay(EGLDisplay display, std::string& reason) {
    if (display == EGL_NO_DISPLAY) {
        reason = "no display (" + lastEglError() + ")";
        return nullptr;
    }
    EGLint major = 0;
    EGLint minor = 0;
    if (!acquireDisplay(display, &major, &minor)) {
        reason = "eglInitialize failed (" + lastEglError() + ")";
        return nullptr;
    }
    reason = missingDisplayFeatures(display, major, minor);
    std::unique_ptr<EglHeadlessContext> context;
    if (reason.empty()) context = createOnDisplay(display, reason);
    if (!context) {
        releaseDisplay(display);
        return nullptr;
    }
    try {
        // From here the context owns the display reference.
        context->finishSetup();
    } catch (const Error& e) {
        reason = e.reason();
        return nullptr;
    }
    return context;
}

struct DisplayCandidate {
    std::string label;
    EGLDisplay display;
};

// Whether EGL device `device` is a software rasterizer (Mesa's llvmpipe device says so with
// EGL_MESA_device_software); false where the driver cannot be asked.
bool isSoftwareDevice(EGLDeviceEXT device, const char* clientExtensions) {
    if (!hasExtension(clientExtensions, "EGL_EXT_device_query")) return false;
    return hasExtension(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS),
                        "EGL_MESA_device_software");
}

// The displays to try, in order: hardware EGL devices first (an NVIDIA GPU with no display is
// one, and with Mesa installed beside its driver, Mesa's surfaceless platform would otherwise
// hand out llvmpipe on a machine with a GPU), then Mesa's surfaceless platform, then software
// devices.
std::vector<DisplayCandidate> platformDisplays(const char* clientExtensions) {
    std::vector<DisplayCandidate> hardware, software;
    if (!hasExtension(clientExtensions, "EGL_EXT_platform_base")) return hardware;
    if (hasExtension(clientExtensions, "EGL_EXT_platform_device") &&
        hasExtension(clientExtensions, "EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (eglQueryDevicesEXT(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                const bool soft = isSoftwareDevice(devices[i], clientExtensions);
                (soft ? software : hardware)
                    .push_back(
                        {"EGL device " + std::to_string(i) + (soft ? " (software)" : ""),
                         eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr)});
            }
        }
    }
    std::vector<DisplayCandidate> candidates = std::move(hardware);
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        candidates.push_back(
            {"Mesa surfaceless platform", eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA,
                                                                   EGL_DEFAULT_DISPLAY, nullptr)});
    }
    candidates.insert(candidates.end(), software.begin(), software.end());
    return candidates;
}

// ---- GLFW ------------------------------------------------------------------------------------

// GLFW reports errors through one process-wide callback; creation reads the latest message to
// explain a failure, later errors become warnings.
std::mutex& glfwMutex() {
    static std::mutex m;
    return m;
}

std::string& glfwLastError() {
    static std::string message;
    return message;
}

int& glfwUsers() {
    static int users = 0;
    return users;
}

// True while creating: the failure becomes the Error's reason, not a warning as well.
bool& glfwQuiet() {
    static bool quiet = false;
    return quiet;
}

void onGlfwError(int code, const char* description) {
    glfwLastError() = description ? description : "GLFW error " + std::to_string(code);
    if (glfwQuiet()) return;
    try {
        logWarning("GLFW: " + glfwLastError());
    } catch (...) {
    }
}

void acquireGlfw() {
    std::lock_guard<std::mutex> lock(glfwMutex());
    if (glfwUsers() == 0) {
        glfwSetErrorCallback(onGlfwError);
        glfwLastError().clear();
        glfwQuiet() = true;
        const bool ok = glfwInit();
        glfwQuiet() = false;
        if (!ok) {
            throw Error(kWindowWhere,
                        "cannot open a window: " + glfwLastError() +
                            " (no display? Set DISPLAY or WAYLAND_DISPLAY, or render headless)");
        }
    }
    ++glfwUsers();
}

void releaseGlfw() {
    std::lock_guard<std::mutex> lock(glfwMutex());
    // glfwTerminate destroys every window, so it waits for the last one.
    if (--glfwUsers() == 0) glfwTerminate();
}

}  // namespace

namespace {
std::atomic<bool>& glDebugAsked() {
    static std::atomic<bool> asked{false};
    return asked;
}
}  // namespace

void setGlDebugRequested(bool requested) {
    glDebugAsked().store(requested);
}

bool glDebugRequested() {
    if (glDebugAsked().load()) return true;
    const char* env = std::getenv("EIKON_GL_DEBUG");
    if (env && *env) return std::strcmp(env, "0") != 0;
#ifdef NDEBUG
    return false;
#else
    return true;
#endif
}

void GlContext::initialize(const std::string& where) {
    version_ = glString(GL_VERSION);
    renderer_ = glString(GL_RENDERER);
    vendor_ = glString(GL_VENDOR);
    if (version_.empty()) throw Error(where, "no current OpenGL context after creating one");
    const int version = epoxy_gl_version();
    major_ = version / 10;
    minor_ = version % 10;
    const std::string found = "\"" + version_ + "\" on \"" + renderer_ + "\"";
    if (version < 43 || epoxy_is_desktop_gl() == 0)
        throw Error(where, "OpenGL 4.3 core is required, found " + found + "; " + kMesaHint);
    limits_ = queryLimits();
    if (limits_.maxComputeWorkGroupInvocations <= 0)
        throw Error(where, "the context has no compute shaders (" + found + "); " + kMesaHint);
    if (glDebugRequested()) {
        enableDebugOutput();
        debugOutput_ = true;
    }
}

void GlContext::finish() const {
    glFinish();
}

std::unique_ptr<GlContext> createHeadlessContext() {
    requireLibraries();
    // Client extensions come from EGL_NO_DISPLAY; null means EGL 1.4 without client extensions.
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    std::string attempts;
    std::string reason;
    for (const DisplayCandidate& candidate : platformDisplays(clientExtensions)) {
        if (std::unique_ptr<GlContext> context = tryDisplay(candidate.display, reason))
            return context;
        attempts += "\n  " + candidate.label + ": " + reason;
    }
    // Last, as it may try a window system (X11, Wayland) that a headless machine lacks.
    if (std::unique_ptr<GlContext> context = tryDisplay(eglGetDisplay(EGL_DEFAULT_DISPLAY), reason))
        return context;
    attempts += "\n  default display: " + reason;
    throw Error(kHeadlessWhere, "no headless OpenGL 4.3 core context could be created; tried:" +
                                    attempts + "\n  hint: " + kMesaHint);
}

GlfwWindowContext::GlfwWindowContext(int width, int height, const std::string& title,
                                     bool visible) {
    acquireGlfw();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, glDebugRequested() ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    glfwLastError().clear();
    glfwQuiet() = true;
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    glfwQuiet() = false;
    if (!window_) {
        const std::string reason = glfwLastError();
        releaseGlfw();
        throw Error(kWindowWhere, "no window with an OpenGL 4.3 core context: " + reason);
    }
    glfwMakeContextCurrent(window_);
    try {
        initialize(kWindowWhere);
    } catch (...) {
        // The destructor does not run for a half-built object.
        glfwDestroyWindow(window_);
        releaseGlfw();
        throw;
    }
}

GlfwWindowContext::~GlfwWindowContext() {
    glfwDestroyWindow(window_);
    releaseGlfw();
}

void GlfwWindowContext::makeCurrent() {
    glfwMakeContextCurrent(window_);
}

void GlfwWindowContext::releaseCurrent() {
    if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
}

void GlfwWindowContext::swapBuffers() {
    glfwSwapBuffers(window_);
}

bool GlfwWindowContext::shouldClose() const {
    return glfwWindowShouldClose(window_) != 0;
}

void GlfwWindowContext::pollEvents() {
    glfwPollEvents();
}

GlfwWindowContext::Size GlfwWindowContext::framebufferSize() const {
    Size size;
    glfwGetFramebufferSize(window_, &size.width, &size.height);
    return size;
}

bool isSoftwareRenderer(const std::string& rendererName) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast"})
        if (rendererName.find(name) != std::string::npos) return true;
    return false;
}

}  // namespace eikon
