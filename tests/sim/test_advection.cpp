#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "sim/advection.h"
#include "sim/advection_problems.h"
#include "smoke_test_fields.h"

using namespace eikon;
using namespace eikon::sim;

namespace {

constexpr AdvectionScheme kSchemes[] = {AdvectionScheme::SemiLagrangian,
                                        AdvectionScheme::MacCormack, AdvectionScheme::Bfecc};

void advectDensity(MacGrid& g, float dt, const AdvectionSettings& s) {
    Array3 next;
    advectField(g, g.density, next, dt, s);
    g.density = std::move(next);
}

}  // namespace

TEST_CASE("advection: density drift in a closed swirl is bounded and falls with resolution",
          "[smoke][advection]") {
    // Closed slab, no sources, a bump of density carried for 0.5 s by a discretely divergence-free
    // swirl at CFL 1. Semi-Lagrangian advection with trilinear sampling is not conservative: each
    // step redistributes the interpolation weights unevenly where the flow strains. Measured here
    // (Release, this commit): semi-Lagrangian −1.9e-2 at 24², −8.8e-3 at 48², first order in h.
    // This is the drift without `conserve_mass` (test_mass_correction.cpp holds the corrected
    // runs to the 1e-5); these bounds are the measured drift with a margin, and the test
    // checks it converges.
    constexpr double kSemiLagrangianDrift = 3e-2;
    // The second-order schemes' limiters clip the dispersive lobes (Lax–Wendroff-like trailing
    // undershoots), which adds mass: measured up to 8.6e-2 (MacCormack + clamp at 24²).
    constexpr double kSecondOrderDrift = 0.15;
    // First order in h: doubling the resolution should roughly halve the drift.
    constexpr double kConvergenceRatio = 0.7;
    for (AdvectionScheme scheme : kSchemes)
        for (Limiter limiter : {Limiter::Clamp, Limiter::Revert}) {
            double drift[2] = {0.0, 0.0};
            for (int r = 0; r < 2; ++r) {
                const int n = r == 0 ? 24 : 48;
                const float h = 1.0f / n;
                MacGrid g(test::closedBox({n, n, 2}, h));
                test::setSwirl(g, 1.0f);
                test::setDensityBump(g, glm::vec3(0.5f * n, 0.7f * n, 1.0f), 0.15f * n);
                const double before = test::totalDensity(g);
                const float dt = h;  // CFL 1 at the peak speed 1
                const int steps = n / 2;
                for (int s = 0; s < steps; ++s) advectDensity(g, dt, {scheme, limiter});
                drift[r] = test::totalDensity(g) / before - 1.0;
                WARN(schemeName(scheme)
                     << (limiter == Limiter::Clamp ? " + clamp" : " + revert") << " at " << n << "x"
                     << n << ": relative density drift after " << steps << " steps = " << drift[r]);
                CHECK(std::fabs(drift[r]) <= (scheme == AdvectionScheme::SemiLagrangian
                                                  ? kSemiLagrangianDrift
                                                  : kSecondOrderDrift));
            }
            CHECK(std::fabs(drift[1]) < kConvergenceRatio * std::fabs(drift[0]));
        }
}

TEST_CASE("advection: Zalesak's slotted disk, error falls with resolution, second order wins",
          "[smoke][advection]") {
    std::map<AdvectionScheme, AdvectionProblemResult> coarse, fine;
    for (AdvectionScheme scheme : kSchemes) {
        const AdvectionSettings s{scheme, Limiter::Clamp};
        coarse[scheme] = zalesakRotation(24, ZalesakShape::Disk, s);
        fine[scheme] = zalesakRotation(48, ZalesakShape::Disk, s);
        for (int n : {24, 48}) {
            const AdvectionProblemResult& r = n == 24 ? coarse[scheme] : fine[scheme];
            WARN("Zalesak " << n << "x" << n << " " << schemeName(scheme) << " + clamp: L1 " << r.l1
                            << ", volume loss " << r.volumeLoss << ", mass change "
                            << r.massChange);
        }
        CHECK(fine[scheme].l1 < coarse[scheme].l1);
    }
    for (const auto* results : {&coarse, &fine}) {
        const double sl = results->at(AdvectionScheme::SemiLagrangian).l1;
        CHECK(results->at(AdvectionScheme::MacCormack).l1 < sl);
        CHECK(results->at(AdvectionScheme::Bfecc).l1 < sl);
    }
}

TEST_CASE("advection: Enright's deformation, error falls with resolution, second order wins",
          "[smoke][advection]") {
    // Period T = 1, a third of Enright's: at these sizes his T = 3 stretches the sphere thinner
    // than a cell and every scheme loses it (`eikon bench advection --period 3` shows it).
    constexpr double kPeriod = 1.0;
    std::map<AdvectionScheme, AdvectionProblemResult> coarse, fine;
    for (AdvectionScheme scheme : kSchemes) {
        const AdvectionSettings s{scheme, Limiter::Clamp};
        coarse[scheme] = enrightDeformation(24, s, kPeriod);
        fine[scheme] = enrightDeformation(32, s, kPeriod);
        for (const auto* r : {&coarse[scheme], &fine[scheme]})
            WARN("Enright T = 1, " << r->resolution << "^3 " << schemeName(scheme)
                                   << " + clamp: L1 " << r->l1 << ", volume loss " << r->volumeLoss
                                   << ", mass change " << r->massChange);
        CHECK(fine[scheme].l1 < coarse[scheme].l1);
    }
    for (const auto* results : {&coarse, &fine}) {
        const double sl = results->at(AdvectionScheme::SemiLagrangian).l1;
        CHECK(results->at(AdvectionScheme::MacCormack).l1 < sl);
        CHECK(results->at(AdvectionScheme::Bfecc).l1 < sl);
    }
}

TEST_CASE("advection: every limited scheme stays in the initial range at CFL up to 10",
          "[smoke][advection]") {
    const int n = 24;
    const float h = 1.0f / n;
    const float peak = 1.0f;
    // Limited results are blends or clamps of the source's own values: no slack is needed beyond
    // one float rounding of a trilinear blend of values in [0, 1].
    constexpr float kRangeSlack = 1e-6f;
    for (float cfl : {0.5f, 1.0f, 2.0f, 5.0f, 10.0f})
        for (AdvectionScheme scheme : kSchemes)
            for (Limiter limiter : {Limiter::Clamp, Limiter::Revert}) {
                MacGrid g(test::closedBox({n, n, 2}, h));
                test::setSwirl(g, peak);
                test::setDensityBump(g, glm::vec3(0.5f * n, 0.7f * n, 1.0f), 0.2f * n);
                const float dt = cfl * h / peak;
                for (int s = 0; s < 10; ++s) advectDensity(g, dt, {scheme, limiter});
                const auto [lo, hi] =
                    std::minmax_element(g.density.values().begin(), g.density.values().end());
                INFO(schemeName(scheme)
                     << (limiter == Limiter::Clamp ? " clamp" : " revert") << " at CFL " << cfl);
                CHECK_FALSE(g.density.firstNonFinite().has_value());
                CHECK(*lo >= -kRangeSlack);
                CHECK(*hi <= 1.0f + kRangeSlack);
            }
}

TEST_CASE("advection: an unlimited second-order scheme does overshoot a sharp edge",
          "[smoke][advection]") {
    // The other side of the range test: without the limiter the correction must leave [0, 1],
    // or the range test would prove nothing.
    const int n = 24;
    MacGrid g(test::closedBox({n, n, 2}, 1.0f / n));
    test::setSwirl(g, 1.0f);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < 2; ++k) g.density(i, j, k) = (i > n / 2 && j > n / 2) ? 1.0f : 0.0f;
    for (int s = 0; s < 5; ++s)
        advectDensity(g, 2.0f / n, {AdvectionScheme::MacCormack, Limiter::None});
    const auto [lo, hi] = std::minmax_element(g.density.values().begin(), g.density.values().end());
    CHECK((*lo < 0.0f || *hi > 1.0f));
}

TEST_CASE("advection: a uniform field comes out of every scheme bit for bit unchanged",
          "[smoke][advection]") {
    // advectState() skips uniform fields (the temperature of a scene without heat sources); this
    // is what makes that skip exact rather than an approximation.
    const int n = 24;
    for (AdvectionScheme scheme : kSchemes)
        for (Limiter limiter : {Limiter::None, Limiter::Clamp, Limiter::Revert}) {
            MacGrid g(test::closedBox({n, n, 2}, 1.0f / n));
            test::setSwirl(g, 1.0f);
            g.temperature.fill(0.3f);
            Array3 next;
            advectField(g, g.temperature, next, 3.0f / n, {scheme, limiter});
            INFO(schemeName(scheme) << " limiter " << int(limiter));
            CHECK(next.values() == g.temperature.values());
        }
}
