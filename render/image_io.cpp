#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <png.h>

#include "core/atomic_write.h"
#include "core/error.h"
#include "render/image.h"

#include "shaders/shared/platform.h"

EK_NAMESPACE_BEGIN
#include "shaders/shared/tone_map.h"
EK_NAMESPACE_END

namespace eikon {
namespace {

// libpng's own handlers print "libpng error: ..." before ours; these keep its reason (and the
// system's, for a failed write) for the one line the caller prints.
struct PngFailure {
    std::string reason;
    int systemError = 0;
};

void onPngError(png_structp png, png_const_charp message) {
    auto* failure = static_cast<PngFailure*>(png_get_error_ptr(png));
    failure->reason = message ? message : "unknown";
    failure->systemError = errno;
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

// Images read back are bounded: a corrupt header must not ask for gigabytes.
constexpr int64_t kMaxImageSide = 32768;
constexpr int64_t kMaxImagePixels = int64_t(1) << 26;

std::string imageSizeProblem(int64_t width, int64_t height) {
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide ||
        width * height > kMaxImagePixels)
        return "its header says " + std::to_string(width) + "x" + std::to_string(height) +
               " pixels, beyond what Eikon reads (" + std::to_string(kMaxImageSide) + " a side, " +
               std::to_string(kMaxImagePixels) + " in all)";
    return "";
}

void checkImageSize(const std::string& path, int64_t width, int64_t height) {
    const std::string problem = imageSizeProblem(width, height);
    if (!problem.empty()) throw Error(path, problem);
}

void writePngFile(const std::string& file, const std::string& nameForErrors, int width, int height,
                  const std::vector<unsigned char>& rgb) {
    FILE* fp = std::fopen(file.c_str(), "wb");
    if (!fp)
        throw Error(nameForErrors, std::string("cannot open for writing: ") + std::strerror(errno));
    PngFailure failure;
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &failure, onPngError, onPngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(fp);
        std::string reason = "libpng failed while writing";
        if (!failure.reason.empty()) reason += ": " + failure.reason;
        if (failure.systemError != 0)
            reason += " (" + std::string(std::strerror(failure.systemError)) + ")";
        throw Error(nameForErrors, reason);
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) png_write_row(png, rgb.data() + size_t(y) * size_t(width) * 3);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    const bool flushed = std::fflush(fp) == 0 && !std::ferror(fp);
    const int flushError = errno;
    if (std::fclose(fp) != 0 || !flushed)
        throw Error(nameForErrors, std::string("could not finish writing: ") +
                                       std::strerror(flushed ? errno : flushError));
}

}  // namespace

std::vector<unsigned char> toneMapToSrgb8(const Image& image, float exposureStops,
                                          ToneCurve curve) {
    const float scale = std::exp2(exposureStops);
    const int code = curve == ToneCurve::Filmic ? EK_TONE_FILMIC : EK_TONE_LINEAR;
    std::vector<unsigned char> out(image.pixels.size() * 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            out[i * 3 + size_t(c)] = (unsigned char)std::lround(
                255.0f * shared::toneMapChannel(image.pixels[i][c], scale, code));
    return out;
}

void writePng(const std::string& path, const Image& image, float exposureStops, ToneCurve curve) {
    writePngRgb8(path, image.width, image.height, toneMapToSrgb8(image, exposureStops, curve));
}

void writePngRgb8(const std::string& path, int width, int height,
                  const std::vector<unsigned char>& rgb) {
    if (rgb.size() != size_t(width) * size_t(height) * 3)
        throw Error(path, "pixel buffer does not match " + std::to_string(width) + "x" +
                              std::to_string(height) + " RGB");
    writeAtomically(path,
                    [&](const std::string& file) { writePngFile(file, path, width, height, rgb); });
}

void writeExr(const std::string& path, const Image& image) {
    writeAtomically(path, [&](const std::string& file) {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        const char* names[4] = {"R", "G", "B", "A"};
        for (const char* n : names) header.channels().insert(n, Imf::Channel(Imf::FLOAT));
        Imf::FrameBuffer fb;
        const size_t xStride = sizeof(glm::vec4);
        const size_t yStride = xStride * size_t(image.width);
        char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
        for (int c = 0; c < 4; ++c)
            fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
        Imf::OutputFile out(file.c_str(), header);
        out.setFrameBuffer(fb);
        out.writePixels(image.height);
    });
}

Image readExr(const std::string& path) {
    try {
        Imf::InputFile in(path.c_str());
        const Imath::Box2i window = in.header().dataWindow();
        const int64_t width = int64_t(window.max.x) - window.min.x + 1;
        const int64_t height = int64_t(window.max.y) - window.min.y + 1;
        checkImageSize(path, width, height);
        Image image{int(width), int(height)};
        Imf::FrameBuffer fb;
        const size_t xStride = sizeof(glm::vec4);
        const size_t yStride = xStride * size_t(image.width);
        char* base = reinterpret_cast<char*>(image.pixels.data()) -
                     (size_t(window.min.x) + size_t(window.min.y) * size_t(image.width)) * xStride;
        const char* names[4] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c)
            fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride,
                                           1, 1, c == 3 ? 1.0 : 0.0));
        in.setFrameBuffer(fb);
        in.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(path, std::string("cannot read as EXR: ") + e.what());
    }
}

Image readPng(const std::string& path) {
    FILE* fp = std::fopen(path.c_str(), "rb");
    if (!fp) throw Error(path, std::string("cannot open: ") + std::strerror(errno));
    PngFailure failure;
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &failure, onPngError, onPngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    // Declared before setjmp: a longjmp back must not skip their destructors' bookkeeping.
    Image image;
    std::vector<unsigned char> row;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(fp);
        throw Error(path, "cannot read as PNG: " + failure.reason);
    }
    png_init_io(png, fp);
    png_read_info(png, info);
    const int64_t width = png_get_image_width(png, info);
    const int64_t height = png_get_image_height(png, info);
    if (!imageSizeProblem(width, height).empty()) {
        failure.reason = imageSizeProblem(width, height);
        png_longjmp(png, 1);
    }
    // Any PNG as 8-bit RGB: palettes and grey expanded, 16 bits cut to 8, alpha dropped.
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_read_update_info(png, info);
    image = Image(int(width), int(height));
    row.resize(size_t(width) * 3);
    for (int y = 0; y < int(height); ++y) {
        png_read_row(png, row.data(), nullptr);
        for (int x = 0; x < int(width); ++x)
            image.at(x, y) = glm::vec4(row[size_t(x) * 3] / 255.0f, row[size_t(x) * 3 + 1] / 255.0f,
                                       row[size_t(x) * 3 + 2] / 255.0f, 1.0f);
    }
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(fp);
    return image;
}

ImageDifference compareImages(const Image& test, const Image& reference) {
    if (test.width != reference.width || test.height != reference.height)
        throw Error("compare", "images differ in size: " + std::to_string(test.width) + "x" +
                                   std::to_string(test.height) + " vs " +
                                   std::to_string(reference.width) + "x" +
                                   std::to_string(reference.height));
    ImageDifference d;
    double sumSq = 0.0, sumAbs = 0.0, sumRef = 0.0;
    for (size_t i = 0; i < test.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double r = reference.pixels[i][c];
            const double diff = double(test.pixels[i][c]) - r;
            sumSq += diff * diff;
            sumAbs += std::abs(diff);
            sumRef += std::abs(r);
            d.maxAbs = std::max(d.maxAbs, std::abs(diff));
            d.referenceMax = std::max(d.referenceMax, r);
        }
    const double n = 3.0 * double(test.pixels.size());
    d.rmse = n > 0 ? std::sqrt(sumSq / n) : 0.0;
    d.meanRelative = sumRef > 0 ? sumAbs / sumRef : 0.0;
    return d;
}

}  // namespace eikon
