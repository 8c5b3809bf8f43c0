#include "render/gl_objects.h"

#include <epoxy/gl.h>

namespace eikon {
namespace {

// Names beyond the next one handed out that are asked about too, for drivers that reuse freed
// names (the next one is then the lowest free name, and live ones may lie above it).
constexpr GLuint kBeyondNext = 1024;

// One kind of GL object: where its count goes, and how to make, delete and recognise a name.
struct NameKind {
    int GlObjectCounts::*count;
    void (*generate)(GLuint*);
    void (*remove)(GLuint);
    bool (*isName)(GLuint);
};

const NameKind kKinds[] = {
    {&GlObjectCounts::textures, [](GLuint* n) { glGenTextures(1, n); },
     [](GLuint n) { glDeleteTextures(1, &n); }, [](GLuint n) { return glIsTexture(n) == GL_TRUE; }},
    {&GlObjectCounts::buffers, [](GLuint* n) { glGenBuffers(1, n); },
     [](GLuint n) { glDeleteBuffers(1, &n); }, [](GLuint n) { return glIsBuffer(n) == GL_TRUE; }},
    {&GlObjectCounts::queries, [](GLuint* n) { glGenQueries(1, n); },
     [](GLuint n) { glDeleteQueries(1, &n); }, [](GLuint n) { return glIsQuery(n) == GL_TRUE; }},
    {&GlObjectCounts::framebuffers, [](GLuint* n) { glGenFramebuffers(1, n); },
     [](GLuint n) { glDeleteFramebuffers(1, &n); },
     [](GLuint n) { return glIsFramebuffer(n) == GL_TRUE; }},
    {&GlObjectCounts::vertexArrays, [](GLuint* n) { glGenVertexArrays(1, n); },
     [](GLuint n) { glDeleteVertexArrays(1, &n); },
     [](GLuint n) { return glIsVertexArray(n) == GL_TRUE; }},
    {&GlObjectCounts::samplers, [](GLuint* n) { glGenSamplers(1, n); },
     [](GLuint n) { glDeleteSamplers(1, &n); }, [](GLuint n) { return glIsSampler(n) == GL_TRUE; }},
};

}  // namespace

bool GlObjectCounts::operator==(const GlObjectCounts& o) const {
    return textures == o.textures && buffers == o.buffers && programs == o.programs &&
           shaders == o.shaders && queries == o.queries && framebuffers == o.framebuffers &&
           vertexArrays == o.vertexArrays && samplers == o.samplers;
}

std::string GlObjectCounts::describe() const {
    return "textures " + std::to_string(textures) + ", buffers " + std::to_string(buffers) +
           ", programs " + std::to_string(programs) + ", shaders " + std::to_string(shaders) +
           ", queries " + std::to_string(queries) + ", framebuffers " +
           std::to_string(framebuffers) + ", vertex arrays " + std::to_string(vertexArrays) +
           ", samplers " + std::to_string(samplers);
}

GlObjectCounts countGlObjects() {
    GlObjectCounts c;
    for (const NameKind& kind : kKinds) {
        GLuint next = 0;
        kind.generate(&next);
        kind.remove(next);
        for (GLuint name = 1; name < next + kBeyondNext; ++name)
            if (name != next && kind.isName(name)) ++(c.*kind.count);
    }
    // Programs and shaders share one namespace: a probe program tells where it stands.
    const GLuint next = glCreateProgram();
    glDeleteProgram(next);
    for (GLuint name = 1; name < next + kBeyondNext; ++name) {
        if (name == next) continue;
        if (glIsProgram(name) == GL_TRUE) ++c.programs;
        if (glIsShader(name) == GL_TRUE) ++c.shaders;
    }
    return c;
}

}  // namespace eikon
