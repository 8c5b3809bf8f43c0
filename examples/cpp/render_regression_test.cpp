// What a user's regression test looks like with Eikon as a library: render a frame in memory and
// compare it with the hash it had when the test was written. The CPU twin, so the bytes are the
// same on every machine (the GPU path equals it only up to float rounding).
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <string>

#include <eikon/eikon.h>
#include <eikon/fields.h>

namespace {

// FNV-1a, 64 bits: enough to notice any changed byte, and nothing to install.
std::uint64_t fnv1a(const std::vector<std::uint8_t>& bytes) {
    std::uint64_t h = 14695981039346656037ull;
    for (std::uint8_t b : bytes) h = (h ^ b) * 1099511628211ull;
    return h;
}

std::string hex(std::uint64_t v) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

}  // namespace

TEST_CASE("the homogeneous cube renders as it did when this test was written") {
    eikon::Session session = eikon::Session::open(EXAMPLE_SCENE, eikon::Device::Cpu);
    session.setImageSize(32, 24);
    const eikon::RenderedImage image = session.render(session.firstFrame());
    REQUIRE(image.width == 32);
    REQUIRE(image.height == 24);
    REQUIRE(image.srgb8.size() == 32 * 24 * 3);
    // Written by running this test once and copying the hash it printed.
    CHECK(hex(fnv1a(image.srgb8)) == "6d0d85765dfbabb9");
}

TEST_CASE("a bad scene is an eikon::Error with the command line's one-line message") {
    try {
        eikon::Session::fromJson("{\"camera\": {\"fov\": 40}}", ".", eikon::Device::Cpu);
        FAIL("no error");
    } catch (const eikon::Error& e) {
        // "./<json text>:/sources: missing required key ..." as eikon render would say of a file
        CHECK(std::string(e.what()).rfind("./<json text>:/", 0) == 0);
    }
}

TEST_CASE("the density the scene loaded is an OpenVDB grid") {
    eikon::Session session = eikon::Session::open(EXAMPLE_SCENE, eikon::Device::Cpu);
    session.setImageSize(8, 6);
    session.render(session.firstFrame());
    const auto density = eikon::fieldGrid(session, "density");
    REQUIRE(density);
    CHECK(density->activeVoxelCount() > 0);
}
