#pragma once
// How many GL objects of each kind are alive in the current context: what a long run (`eikon
// bench soak`) and the tests watch to show that frames create no GL object they do not delete.
// GL has no query for it, so every name the driver may have handed out is asked about (glIs*).
#include <string>

namespace eikon {

struct GlObjectCounts {
    int textures = 0;
    int buffers = 0;
    int programs = 0;
    int shaders = 0;
    int queries = 0;
    int framebuffers = 0;
    int vertexArrays = 0;
    int samplers = 0;

    int total() const {
        return textures + buffers + programs + shaders + queries + framebuffers + vertexArrays +
               samplers;
    }
    bool operator==(const GlObjectCounts& o) const;
    bool operator!=(const GlObjectCounts& o) const { return !(*this == o); }
    // "textures 5, buffers 3, ..." for messages.
    std::string describe() const;
};

// Needs a current context. For each kind, one name is generated and deleted again to learn where
// the driver's names stand (Mesa hands out names above every name it gave before, by default),
// and every name below it and 1024 beyond it (drivers that reuse names) is asked about: cheap
// for the few thousand names a run makes, and exact, since it asks the driver itself. An object
// counts once it has been bound or used (what glIs* answers), as GL defines it.
GlObjectCounts countGlObjects();

}  // namespace eikon
