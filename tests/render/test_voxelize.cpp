// Voxelization of closed meshes into coverage (render/voxelize.h, Sun et al. 2008 §4.1): exact
// sample counts where the answer is a lattice count (ties on edges and vertices included), the
// sphere's volume and normals against the closed form, translation, the blur, the GPU against
// the CPU twin, and bad meshes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>

#include <epoxy/gl.h>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/mesh_primitives.h"
#include "render/gl_context.h"
#include "render/voxelize.h"
#include "shaders/shared/platform.h"

using namespace eikon;

// The shared blur as the GPU runs it, an exp a tap (no EK_BLUR_WEIGHT_TABLE here): the reference
// for the twin's table of weights.
EK_NAMESPACE_BEGIN
struct BlurWithExpsCpu {
    const float* source;
    ivec3 res;
    float fetchUnblurred(ivec3 v) const {
        return source[(size_t(v.z) * size_t(res.y) + size_t(v.y)) * size_t(res.x) + size_t(v.x)];
    }
#include "shaders/shared/gaussian_blur.h"
};
EK_NAMESPACE_END

namespace {

constexpr double kPi = 3.14159265358979323846;

RenderVolume unitVolume(int n) {
    return {Bounds3{glm::vec3(0.0f), glm::vec3(1.0f)}, glm::ivec3(n)};
}

double coveredVolume(const std::vector<float>& coverage, const RenderVolume& volume) {
    double sum = 0.0;
    for (float c : coverage) sum += double(c);
    const glm::vec3 v = volume.voxelSize();
    return sum * double(v.x) * double(v.y) * double(v.z);
}

// An octahedron |x − c|₁ < r with its six vertices given exactly; coordinates dyadic so that
// moving it by whole voxels moves every fine coordinate exactly.
TriangleMesh octahedron(glm::vec3 c, float r) {
    TriangleMesh m;
    m.positions = {c + glm::vec3(r, 0, 0), c - glm::vec3(r, 0, 0), c + glm::vec3(0, r, 0),
                   c - glm::vec3(0, r, 0), c + glm::vec3(0, 0, r), c - glm::vec3(0, 0, r)};
    // +x 0, −x 1, +y 2, −y 3, +z 4, −z 5; wound outward.
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

unsigned makeR32F(glm::ivec3 res, const std::vector<float>* data = nullptr) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_R32F, res.x, res.y, res.z);
    if (data)
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, res.x, res.y, res.z, GL_RED, GL_FLOAT,
                        data->data());
    return tex;
}

std::vector<float> download(unsigned tex, size_t count) {
    std::vector<float> out(count);
    glBindTexture(GL_TEXTURE_3D, tex);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RED, GL_FLOAT, out.data());
    return out;
}

}  // namespace

TEST_CASE("generated meshes are closed and wound outward", "[voxelize]") {
    CHECK(signedVolume(boxMesh(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f))) == Approx(6.0));
    const TriangleMesh sphere = icosphere(glm::vec3(0.0f), 1.0f, 3);
    CHECK(sphere.triangles.size() == 1280);
    CHECK(signedVolume(sphere) > 0.98 * 4.0 / 3.0 * kPi);
    CHECK(signedVolume(sphere) < 4.0 / 3.0 * kPi);
    CHECK(signedVolume(octahedron(glm::vec3(0.0f), 1.0f)) == Approx(4.0 / 3.0));
    const TriangleMesh uv = uvSphere(glm::vec3(0.0f), 1.0f, 100, 51);
    CHECK(uv.triangles.size() == 10000);
    CHECK(signedVolume(uv) > 0.99 * 4.0 / 3.0 * kPi);
    CHECK(signedVolume(uv) < 4.0 / 3.0 * kPi);
}

TEST_CASE("a box whose face diagonals run through column centres covers exactly its volume",
          "[voxelize]") {
    // [0.25, 0.75]³ at 16³: 32 fine samples per axis inside, none on a face; the two triangles
    // of each z face share a diagonal that passes exactly through 32 column centres, so a
    // crossing counted twice or missed there would flip a whole column above it.
    const RenderVolume volume = unitVolume(16);
    const auto coverage = voxelizeCoverageCpu(boxMesh(glm::vec3(0.25f), glm::vec3(0.75f)), volume);
    CHECK(coveredVolume(coverage, volume) == 0.125);
    CHECK(coverage[volume.voxelCount() / 2 + 8 * 16 + 8] == 1.0f);  // a voxel inside
    CHECK(coverage[0] == 0.0f);
}

TEST_CASE("edges and vertices on column centres are counted once: an octahedron's lattice count",
          "[voxelize]") {
    // Apex and equator vertices, and the edges along x and y, lie exactly on fine column centres
    // (the fine grid of 16³ has 64 samples per axis; centres at (i + ½)/64). z samples sit half a
    // sample off the vertices, so no sample lies on a face: the count is exact.
    const RenderVolume volume = unitVolume(16);
    const float fine = 1.0f / 64.0f;
    const glm::vec3 c(32.5f * fine, 30.5f * fine, 32.0f * fine);
    const float r = 10.0f * fine;
    const auto coverage = voxelizeCoverageCpu(octahedron(c, r), volume);
    std::int64_t expected = 0;
    for (int k = 0; k < 64; ++k)
        for (int j = 0; j < 64; ++j)
            for (int i = 0; i < 64; ++i) {
                const glm::vec3 d = (glm::vec3(i, j, k) + 0.5f) * fine - c;
                if (std::abs(d.x) + std::abs(d.y) + std::abs(d.z) < r) ++expected;
            }
    double samples = 0.0;
    for (float v : coverage) samples += double(v) * 64.0;
    CHECK(samples == double(expected));
}

TEST_CASE("a voxelized sphere holds 4/3 pi r^3 within 1 % at 64^3", "[voxelize]") {
    const RenderVolume volume = unitVolume(64);
    const float r = 0.3f;
    const TriangleMesh sphere = icosphere(glm::vec3(0.5f), r, 5);  // 20,480 triangles
    const auto coverage = voxelizeCoverageCpu(sphere, volume);
    const double exact = 4.0 / 3.0 * kPi * double(r) * double(r) * double(r);
    const double covered = coveredVolume(coverage, volume);
    INFO("covered " << covered << ", sphere " << exact << ", polyhedron " << signedVolume(sphere));
    CHECK(std::abs(covered - exact) / exact < 0.01);
    // Against the polyhedron actually voxelized, the sampling error alone.
    CHECK(std::abs(covered - signedVolume(sphere)) / signedVolume(sphere) < 2e-3);
}

TEST_CASE("the normal from the blurred coverage's gradient is the sphere's within 3 degrees",
          "[voxelize]") {
    const RenderVolume volume = unitVolume(64);
    const glm::vec3 centre(0.5f);
    const auto blurred = blurCoverageCpu(voxelizeCoverageCpu(icosphere(centre, 0.3f, 5), volume),
                                         volume.resolution, {});
    const glm::ivec3 res = volume.resolution;
    auto at = [&](int x, int y, int z) {
        return blurred[(size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x)];
    };
    double worstDeg = 0.0;
    int band = 0;
    for (int z = 1; z < res.z - 1; ++z)
        for (int y = 1; y < res.y - 1; ++y)
            for (int x = 1; x < res.x - 1; ++x) {
                const float c = at(x, y, z);
                if (c < 0.05f || c > 0.95f) continue;  // the surface band
                const glm::vec3 gradient(at(x + 1, y, z) - at(x - 1, y, z),
                                         at(x, y + 1, z) - at(x, y - 1, z),
                                         at(x, y, z + 1) - at(x, y, z - 1));
                // n grows inward (n = 1 + coverage·(ior − 1)), so the outward normal is −∇n.
                const glm::vec3 normal = -glm::normalize(gradient);
                const glm::vec3 analytic = glm::normalize(volume.voxelCenter(x, y, z) - centre);
                const double cosine = std::min(1.0, double(glm::dot(normal, analytic)));
                worstDeg = std::max(worstDeg, std::acos(cosine) * 180.0 / kPi);
                ++band;
            }
    INFO("worst angle " << worstDeg << " degrees over " << band << " band voxels");
    CHECK(band > 5000);
    CHECK(worstDeg < 3.0);
}

TEST_CASE("moving a mesh by whole voxels moves its coverage by as many voxels", "[voxelize]") {
    const RenderVolume volume = unitVolume(16);
    const float fine = 1.0f / 64.0f;
    const TriangleMesh mesh = octahedron(glm::vec3(20.5f, 24.5f, 22.0f) * fine, 9.25f * fine);
    const auto a = voxelizeCoverageCpu(mesh, volume);
    const auto b =
        voxelizeCoverageCpu(translated(mesh, glm::vec3(2.0f, 0.0f, 3.0f) / 16.0f), volume);
    int compared = 0, differing = 0;
    for (int z = 0; z + 3 < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x + 2 < 16; ++x) {
                const size_t from = (size_t(z) * 16 + size_t(y)) * 16 + size_t(x);
                const size_t to = (size_t(z + 3) * 16 + size_t(y)) * 16 + size_t(x + 2);
                ++compared;
                if (a[from] != b[to]) ++differing;
            }
    CHECK(compared > 2000);
    CHECK(differing == 0);
    CHECK(coveredVolume(a, volume) == coveredVolume(b, volume));
}

TEST_CASE("the blur keeps a constant, spreads an impulse by the Gaussian, and keeps mass inside",
          "[voxelize]") {
    const glm::ivec3 res(12, 11, 13);
    const size_t count = size_t(res.x * res.y * res.z);
    for (float v : blurCoverageCpu(std::vector<float>(count, 0.7f), res, {}))
        CHECK(v == Approx(0.7f).epsilon(1e-6));
    // Mass is kept where no voxel the impulse reaches is within a radius of a face (those
    // renormalize their weights): 19³ with the impulse in the middle.
    const glm::ivec3 big(19);
    std::vector<float> impulse(size_t(19 * 19 * 19), 0.0f);
    const size_t centre = (size_t(9) * 19 + 9) * 19 + 9;
    impulse[centre] = 1.0f;
    const auto blurred = blurCoverageCpu(impulse, big, {});
    double norm = 0.0;
    for (int d = -4; d <= 4; ++d) norm += std::exp(-d * d / (2.0 * 1.5 * 1.5));
    CHECK(blurred[centre] == Approx(std::pow(1.0 / norm, 3.0)).epsilon(1e-5));
    CHECK(blurred[centre + 1] ==
          Approx(std::pow(1.0 / norm, 3.0) * std::exp(-1.0 / 4.5)).epsilon(1e-5));
    double total = 0.0;
    for (float v : blurred) total += double(v);
    CHECK(total == Approx(1.0).epsilon(1e-5));
}

TEST_CASE("the twin's blur, with its weights taken once, gives an exp a tap's floats to the bit",
          "[voxelize]") {
    const glm::ivec3 res(13, 6, 17);  // y shorter than the default window: renormalized everywhere
    std::vector<float> coverage(size_t(res.x * res.y * res.z));
    uint32_t state = 12345u;
    for (float& c : coverage) {
        state = state * 1664525u + 1013904223u;
        c = float(state >> 8) / float(1u << 24);
    }
    for (const IndexBlurSettings settings :
         {IndexBlurSettings{}, IndexBlurSettings{0.8f, 2}, IndexBlurSettings{2.3f, 7}}) {
        INFO("sigma " << settings.sigmaVoxels << ", radius " << settings.radiusVoxels);
        std::vector<float> a = coverage, b(coverage.size());
        for (int axis = 0; axis < 3; ++axis) {
            shared::BlurWithExpsCpu kernel{a.data(), res};
            for (int z = 0; z < res.z; ++z)
                for (int y = 0; y < res.y; ++y)
                    for (int x = 0; x < res.x; ++x)
                        b[(size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x)] =
                            kernel.gaussianBlurAlongAxis(glm::ivec3(x, y, z), res, axis,
                                                         settings.sigmaVoxels,
                                                         settings.radiusVoxels);
            std::swap(a, b);
        }
        const std::vector<float> twin = blurCoverageCpu(coverage, res, settings);
        REQUIRE(twin.size() == a.size());
        CHECK(std::memcmp(twin.data(), a.data(), a.size() * sizeof(float)) == 0);
    }
}

TEST_CASE("bad meshes are rejected naming the mesh", "[voxelize]") {
    TriangleMesh mesh = boxMesh(glm::vec3(0.0f), glm::vec3(1.0f));
    CHECK_NOTHROW(checkMeshForVoxelization(mesh, "box.obj"));
    mesh.positions[3].y = std::nanf("");
    CHECK_THROWS_WITH(checkMeshForVoxelization(mesh, "box.obj"),
                      Catch::Contains("box.obj") && Catch::Contains("vertex 3 is not finite"));
    mesh = boxMesh(glm::vec3(0.0f), glm::vec3(1.0f));
    mesh.triangles[5].z = 8;
    CHECK_THROWS_WITH(checkMeshForVoxelization(mesh, "box.obj"),
                      Catch::Contains("triangle 5 uses vertex 8 of 8"));
}

TEST_CASE("GPU voxelization and blur equal the CPU twin", "[voxelize][gpu]") {
    auto context = createHeadlessContext();
    const RenderVolume volume{Bounds3{glm::vec3(-1.0f, -0.8f, -1.2f), glm::vec3(1.1f, 1.0f, 0.9f)},
                              glm::ivec3(24, 20, 28)};
    // An off-centre sphere that pokes out of the volume on one side, and a tilted box.
    TriangleMesh mesh = icosphere(glm::vec3(0.3f, 0.1f, -0.2f), 0.9f, 3);
    const TriangleMesh box = boxMesh(glm::vec3(-0.9f, -0.7f, 0.3f), glm::vec3(-0.2f, 0.4f, 0.8f));
    const auto base = unsigned(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), box.positions.begin(), box.positions.end());
    for (const glm::uvec3& t : box.triangles) mesh.triangles.push_back(t + base);

    const auto cpu = voxelizeCoverageCpu(mesh, volume);
    const unsigned tex = makeR32F(volume.resolution);
    MeshVoxelizerGpu voxelizer;
    voxelizer.voxelize(mesh, volume, tex);
    const auto gpu = download(tex, volume.voxelCount());
    size_t differing = 0;
    for (size_t i = 0; i < cpu.size(); ++i) differing += cpu[i] != gpu[i] ? 1 : 0;
    INFO(differing << " of " << cpu.size() << " voxels differ");
    CHECK(differing == 0);

    const auto cpuBlurred = blurCoverageCpu(cpu, volume.resolution, {});
    voxelizer.blur(tex, volume.resolution, {});
    const auto gpuBlurred = download(tex, volume.voxelCount());
    double worst = 0.0;
    for (size_t i = 0; i < cpu.size(); ++i)
        worst = std::max(worst, double(std::abs(gpuBlurred[i] - cpuBlurred[i])));
    INFO("max |GPU - CPU| after the blur " << worst);
    CHECK(worst < 1e-6);
    // Again, moved, into the same volume: the kept bit columns must start from zero.
    const TriangleMesh moved = translated(mesh, glm::vec3(0.05f, -0.1f, 0.02f));
    voxelizer.voxelize(moved, volume, tex);
    CHECK(download(tex, volume.voxelCount()) == voxelizeCoverageCpu(moved, volume));
    glDeleteTextures(1, &tex);
}
