#pragma once
// Eikon as a library: load a scene (a file or JSON text) or a VDB cache, step its simulations and
// animation to a frame, render frames to images in memory, change the camera, lights, materials
// and image size between frames, choose the backend. Nothing here exposes OpenGL or TBB; fields
// as OpenVDB grids are in eikon/fields.h. Every call that fails throws eikon::Error whose what()
// is the command line's one-line message ("scene.json:/lights/0/intensity: expected ...").
//
//     #include <eikon/eikon.h>
//     eikon::Session session = eikon::Session::open("glass_sphere_fog.json");
//     session.setImageSize(320, 240);
//     eikon::RenderedImage image = session.render(0);  // image.rgb, image.srgb8
//
// CMake: find_package(Eikon REQUIRED) and target_link_libraries(app PRIVATE Eikon::eikon).
// A Session is used by one thread at a time; separate Sessions are independent.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "eikon/error.h"

namespace eikon {

// Which backend renders: the GPU (OpenGL 4.3 compute, headless), the CPU twin (the same shared
// code on the CPU), or Auto: the GPU when OpenGL is hardware, the CPU twin when it is a software
// rasterizer or missing. Images are the same up to float rounding.
enum class Device { Auto, Gpu, Cpu };

using Vec3 = std::array<float, 3>;

struct RenderedImage {
    int frame = 0;
    // A render's or an EXR's rgb is linear radiance; a PNG read by readImage holds display
    // values (srgb8 / 255) and is not linear.
    bool linear = true;
    int width = 0;
    int height = 0;
    std::vector<float> rgb;            // linear radiance, 3 floats a pixel, row 0 at the top
    std::vector<float> transmittance;  // a float a pixel: how much of the background shows
    std::vector<std::uint8_t> srgb8;   // the PNG's pixels: tone-mapped 8-bit sRGB, 3 a pixel
    // Writes the PNG eikon render writes for this frame (byte for byte), or a linear EXR when the
    // path ends in .exr; through a temporary file, so a failure leaves no half file.
    void write(const std::string& path) const;
    // Kept for write(): the scene's exposure (stops) and tone curve (0 linear, 1 filmic).
    float exposure = 0.0f;
    int toneCurve = 1;
};

struct Camera {
    Vec3 position{0.0f, 0.0f, 5.0f};
    Vec3 lookAt{0.0f, 0.0f, 0.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float horizontalFovDegrees = 45.0f;
};

enum class LightKind { Point, Directional, Spot };

struct Light {
    LightKind kind = LightKind::Directional;
    Vec3 position{0.0f, 0.0f, 0.0f};    // point and spot lights
    Vec3 direction{0.0f, -1.0f, 0.0f};  // directional and spot lights: the way light travels
    Vec3 color{1.0f, 1.0f, 1.0f};
    float intensity = 1.0f;  // irradiance (directional) or radiant intensity per sr
    float coneAngleDegrees = 30.0f;
    float coneSoftnessDegrees = 5.0f;
    // Directional: the angle its disc subtends (soft shadows; plane_sweep and photons draw it).
    float angularDiameterDegrees = 0.0f;
};

// A material's optics (docs/scene-format.md#materials); per-unit-density coefficients.
struct Material {
    std::string name;
    std::string field;  // the field it reads (read-only here)
    Vec3 absorption{0.0f, 0.0f, 0.0f};
    Vec3 scattering{0.0f, 0.0f, 0.0f};
    float anisotropy = 0.0f;  // Henyey–Greenstein g, in (−1, 1)
    Vec3 emission{0.0f, 0.0f, 0.0f};
    float ior = 1.0f;   // n_d with dispersion, the green channel's
    float abbe = 0.0f;  // Abbe number V_d: red and blue part from ior; 0: no dispersion
    // Transfer function: [value, amount] points, the material reading amount(f) in place of its
    // field's value f; empty: f itself (docs/scene-format.md#materials, "transfer").
    std::vector<std::array<float, 2>> transfer;
    // Particle colour (docs/scene-format.md#materials, "particle_color"): what the material
    // scatters and emits is tinted by a colour map by name over particleColorRange of its field's
    // values, or through [value, r, g, b] points (linear colours); both empty: no tint.
    std::string particleColorMap;
    std::array<float, 2> particleColorRange{0.0f, 1.0f};
    std::vector<std::array<float, 4>> particleColorPoints;
};

// How far an image is from its reference, as `eikon regress` measures it (docs/regress.md): over
// RGB, linear when both are (PSNR's peak then the reference's largest value), else on the 8-bit
// display values (peak 1); SSIM always on the luma of display values (a linear image through the
// PNG writer's tone map). Throws eikon::Error when the sizes differ.
struct ImageMetrics {
    double rmse = 0.0;
    double maxAbs = 0.0;
    double meanRelative = 0.0;
    double psnr = 0.0;  // dB; infinite for equal images
    double ssim = 1.0;
};
ImageMetrics compareImages(const RenderedImage& test, const RenderedImage& reference);

// Reads a PNG (display values, linear = false) or an EXR (linear), told apart by the extension.
RenderedImage readImage(const std::string& path);

class Session {
public:
    // A scene file, a VDB file or a VDB sequence pattern (as `eikon render` takes them).
    static Session open(const std::string& path, Device device = Device::Auto);
    // A scene as JSON text; relative paths in it are relative to `baseDirectory`.
    static Session fromJson(const std::string& json, const std::string& baseDirectory = ".",
                            Device device = Device::Auto);

    Session(Session&&) noexcept;
    Session& operator=(Session&&) noexcept;
    ~Session();

    int firstFrame() const;
    int lastFrame() const;
    // One line: which backend renders and why ("CPU twin (TBB), as asked").
    std::string deviceDescription() const;

    // Steps the simulations and animation to `frame` without rendering. Any frame, in any order:
    // a frame holds the same state however it is reached (the live simulation restarts from the
    // scene's first frame when asked for an earlier frame).
    void stepTo(int frame);
    // Renders `frame` (stepping to it first).
    RenderedImage render(int frame);

    // Between frames: what the next render uses. Keyframe tracks that drive the camera or a
    // light still win at the frames they cover.
    Camera camera() const;
    void setCamera(const Camera& camera);
    void setImageSize(int width, int height);
    std::size_t lightCount() const;
    Light light(std::size_t index) const;
    void setLight(std::size_t index, const Light& light);
    std::vector<std::string> materialNames() const;
    Material material(const std::string& name) const;
    void setMaterial(const Material& material);  // by its name; the field cannot change

    struct Impl;  // the scene, its driver and its renderer (api/session_impl.h)
    Impl& impl() { return *impl_; }

private:
    explicit Session(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace eikon
