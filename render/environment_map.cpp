#include "render/environment_map.h"

#include <filesystem>
#include <system_error>

#include <epoxy/gl.h>

#include "core/error.h"

namespace eikon {

Image readEnvironmentImage(const std::string& file, const std::string& jsonPath) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw Error(jsonPath, "no such file '" + file + "'");
    if (!std::filesystem::is_regular_file(file, ec))
        throw Error(jsonPath, "'" + file + "' is not a regular file");
    Image image;
    try {
        image = readExr(file);
    } catch (const Error& e) {
        // readExr's message names the file; the scene's JSON path says who asked for it.
        throw Error(jsonPath,
                    "'" + file + "' is not an equirectangular EXR image (" + e.reason() + ")");
    }
    if (image.width < 1 || image.height < 1)
        throw Error(jsonPath, "'" + file + "' holds no pixels");
    return image;
}

EnvironmentMap::~EnvironmentMap() {
    if (texture_) glDeleteTextures(1, &texture_);
}

void EnvironmentMap::update(const Scene& scene) {
    const EnvironmentSpec& env = scene.environment;
    const std::string wanted = env.type == EnvironmentType::Image ? env.file : std::string();
    if (wanted == file_) return;
    file_.clear();
    image_ = Image();
    if (texture_) {
        glDeleteTextures(1, &texture_);
        texture_ = 0;
    }
    if (wanted.empty()) return;
    const std::string jsonPath = scene.path + ":/environment/file";
    image_ = readEnvironmentImage(wanted, jsonPath);
    ++loads_;
    if (gpu_) {
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
        if (image_.width > maxSize || image_.height > maxSize)
            throw Error(jsonPath, "'" + wanted + "' is " + std::to_string(image_.width) + "x" +
                                      std::to_string(image_.height) +
                                      " pixels; the GPU takes at most " + std::to_string(maxSize) +
                                      " per side");
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, image_.width, image_.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image_.width, image_.height, GL_RGBA, GL_FLOAT,
                        image_.pixels.data());
        // texelFetch ignores filtering; nearest keeps the texture complete without mipmaps.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    file_ = wanted;
}

}  // namespace eikon
