// The photon march in rounds with the active photons compacted between them, and the stop rule
// (render/transport/photons/photon_tracing.h PhotonSettings::stepsPerRound, stopFraction), on the
// CPU twin and on the GPU (shaders/photon_trace.comp, photon_round.comp): the round size alone
// changes nothing, so compaction loses and duplicates no photon; the stop rule cuts only the last
// few photons, keeps the energy balance, and the GPU cuts exactly the twin's.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/gl_context.h"
#include "support/photon_gpu_compare.h"

using namespace eikon;
using eikon::test::GpuRun;
using eikon::test::PhotonScene;
using eikon::test::requireIdentical;
using eikon::test::sameBits;

namespace {

// Everything but the round count: what must not depend on the round size.
void requireSameTrace(const PhotonResultCpu& a, const PhotonResultCpu& b) {
    REQUIRE(a.photons.size() == b.photons.size());
    CHECK(a.photonsTraced == b.photonsTraced);
    CHECK(a.steps == b.steps);
    CHECK(a.photonsCut == b.photonsCut);
    CHECK(a.totals.escaped == b.totals.escaped);
    CHECK(a.totals.extinguished == b.totals.extinguished);
    CHECK(a.totals.dropped == b.totals.dropped);
    CHECK(sameBits(a.photons, b.photons));
    CHECK(sameBits(a.radiance, b.radiance));
    CHECK(sameBits(a.direction, b.direction));
}

double maxRelativeImbalance(const PhotonTotals& t) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double sum = t.escaped[c] + t.extinguished[c] + t.dropped[c] + t.received[c];
        worst = std::max(worst, std::abs(sum - t.emitted[c]) / t.emitted[c]);
    }
    return worst;
}

// A soft n = 1.5 ball that absorbs, so that the flux a photon loses is carried across rounds.
PhotonScene absorbingBall() {
    return PhotonScene(
        32, 1.5f, glm::vec3(4.0f, 6.0f, 10.0f), glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f)),
        [](glm::vec3 x) { return 0.5f - 0.5f * std::tanh((glm::length(x) - 0.5f) / 0.1f); },
        glm::vec3(1.0f, 0.7f, 0.4f));
}

// A sharp n = 2.4 ball under grazing light, absorbing a little: photons that skim it and bounce
// inside take several times the median's steps, so a few of them march long after the rest.
PhotonScene grazingBall() {
    return PhotonScene(32, 2.4f, glm::vec3(0.3f, 0.6f, 1.0f),
                       glm::normalize(glm::vec3(1.0f, -0.002f, 0.0f)),
                       [](glm::vec3 x) { return glm::length(x) < 0.5f ? 1.0f : 0.0f; });
}

constexpr int kHugeRound = 1 << 20;  // more than the step cap: one round

}  // namespace

TEST_CASE("without the stop rule the round size changes nothing but the rounds", "[photons]") {
    const PhotonScene s = absorbingBall();
    PhotonSettings settings;
    settings.photonsPerSide = 48;
    settings.stopFraction = 0.0f;
    settings.stepsPerRound = kHugeRound;
    const PhotonResultCpu once = s.trace(settings);
    CHECK(once.rounds == 1);
    for (int k : {1, 3, PhotonSettings{}.stepsPerRound}) {
        settings.stepsPerRound = k;
        const PhotonResultCpu r = s.trace(settings);
        INFO(k << " steps per round: " << r.rounds << " rounds, " << r.steps << " steps");
        requireSameTrace(r, once);
        CHECK(r.rounds > 1);
    }
}

TEST_CASE("the stop rule cuts the last few photons, the energy still balances", "[photons]") {
    const PhotonScene s = grazingBall();
    PhotonSettings settings;
    settings.photonsPerSide = 64;
    settings.stepsPerRound = 4;
    settings.stopFraction = 0.0f;
    const PhotonResultCpu all = s.trace(settings);
    // Ten times the default, to cut more than the one photon the default cuts here.
    settings.stopFraction = 0.01f;
    const PhotonResultCpu stopped = s.trace(settings);
    INFO("without the rule: " << all.steps << " steps, " << all.rounds
                              << " rounds; with it: " << stopped.steps << " steps, "
                              << stopped.rounds << " rounds, " << stopped.photonsCut << " of "
                              << stopped.photonsTraced << " photons cut");
    REQUIRE(all.photonsCut == 0);
    CHECK(stopped.photonsCut > 0);
    // Cut when fewer than stopFraction of the traced photons were left.
    CHECK(double(stopped.photonsCut) < settings.stopFraction * double(stopped.photonsTraced));
    CHECK(stopped.steps < all.steps);
    CHECK(stopped.rounds < all.rounds);
    CHECK(maxRelativeImbalance(stopped.totals) < 1e-3);
    CHECK(stopped.totals.dropped.x > all.totals.dropped.x);
    // Only the cut photons differ, and each was cut after the rounds before the cutting one.
    const float stepsAtCut = float(settings.stepsPerRound * (stopped.rounds - 1));
    int cut = 0, otherwiseDifferent = 0, cutElsewhere = 0;
    for (size_t i = 0; i < all.photons.size(); ++i) {
        const shared::GpuPhoton& p = stopped.photons[i];
        if (int(p.position.w) == EK_PHOTON_CUT) {
            ++cut;
            cutElsewhere += p.direction.w != stepsAtCut;
        } else {
            otherwiseDifferent += !sameBits(&p, &all.photons[i], sizeof(p));
        }
    }
    CHECK(cut == stopped.photonsCut);
    CHECK(cutElsewhere == 0);
    CHECK(otherwiseDifferent == 0);
}

TEST_CASE("GPU rounds: any round size gives the CPU twin's photons", "[photons][gpu]") {
    // Compaction on the GPU appends in whatever order invocations finish; with every photon's
    // final state and every deposit equal to the twin's, none was lost or marched twice.
    auto context = createHeadlessContext();
    GpuRun gpu;
    const PhotonScene s = absorbingBall();
    PhotonSettings settings;
    settings.photonsPerSide = 48;
    settings.stopFraction = 0.0f;
    for (int k : {1, PhotonSettings{}.stepsPerRound, kHugeRound}) {
        settings.stepsPerRound = k;
        INFO(k << " steps per round");
        requireIdentical(gpu.trace(s, settings), s.trace(settings));
    }
}

TEST_CASE("GPU stop rule: the twin's photons cut, the same bits run after run", "[photons][gpu]") {
    auto context = createHeadlessContext();
    GpuRun gpu;
    const PhotonScene s = grazingBall();
    PhotonSettings settings;
    settings.photonsPerSide = 64;
    settings.stepsPerRound = 4;
    settings.stopFraction = 0.01f;
    const PhotonResultCpu one = gpu.trace(s, settings);
    CHECK(one.photonsCut > 0);
    requireIdentical(one, s.trace(settings));
    requireIdentical(gpu.trace(s, settings), one);
}
