#pragma once
// The scene's environment image ("environment": {"type": "image"}): an equirectangular linear EXR
// read once per change of its path (not every frame), kept in memory for the CPU twin and, on
// the GPU, uploaded once into the RGBA32F texture that shaders/volume_bindings.glsl samples on
// EK_UNIT_ENVIRONMENT (shaders/shared/bindings.h). Core keeps only the path: it cannot read images.
#include <string>

#include "core/scene.h"
#include "render/image.h"

namespace eikon {

// Reads an environment image. Throws eikon::Error whose where() is `jsonPath` (e.g.
// "scene.json:/environment/file") and whose reason names `file`: a missing file, a folder, a file
// that is not an EXR, an empty image.
Image readEnvironmentImage(const std::string& file, const std::string& jsonPath);

class EnvironmentMap {
public:
    // gpu: keep a texture too (needs a current GL context for update() and the destructor).
    explicit EnvironmentMap(bool gpu) : gpu_(gpu) {}
    ~EnvironmentMap();
    EnvironmentMap(const EnvironmentMap&) = delete;
    EnvironmentMap& operator=(const EnvironmentMap&) = delete;

    // Holds the image of scene.environment when its type is Image, reading (and uploading) it
    // only when the path differs from the last one; holds nothing for the other types.
    void update(const Scene& scene);

    const Image& image() const { return image_; }  // empty (0×0) when the scene has no image
    unsigned texture() const { return texture_; }  // 0 when none (or on the CPU)
    int loads() const { return loads_; }           // how often a file was read

private:
    bool gpu_;
    std::string file_;  // the path image_ came from; empty when none
    Image image_;
    unsigned texture_ = 0;
    int loads_ = 0;
};

}  // namespace eikon
