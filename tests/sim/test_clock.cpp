#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "sim/clock.h"

using eikon::SimulationClock;

TEST_CASE("clock maps frames to time and picks substeps by CFL", "[clock]") {
    SimulationClock clock(24.0, 1.0);
    CHECK(clock.timeOfFrame(48) == Approx(2.0));
    // speed 48 voxel-units/s, voxel 1, frame 1/24 s: CFL 2 per frame -> 2 substeps at CFL 1.
    CHECK(clock.substepsFor(48.0, 1.0) == 2);
    CHECK(clock.substepsFor(47.9, 1.0) == 2);
    CHECK(clock.substepsFor(24.0, 1.0) == 1);
    CHECK(clock.substepsFor(0.0, 1.0) == 1);
    SimulationClock loose(24.0, 5.0);
    CHECK(loose.substepsFor(240.0, 1.0) == 2);
}

TEST_CASE("substeps of frame f end between the times of frames f - 1 and f", "[clock]") {
    SimulationClock clock(24.0, 1.0);
    // Frame 5's three substeps end at 4⅓, 4⅔ and 5 frames; the last exactly at the frame's time,
    // bit for bit, so a simulated frame and a rendered one evaluate tracks at the same instant.
    CHECK(clock.timeOfSubstep(5, 0, 3) == Approx((4.0 + 1.0 / 3.0) / 24.0));
    CHECK(clock.timeOfSubstep(5, 1, 3) == Approx((4.0 + 2.0 / 3.0) / 24.0));
    CHECK(clock.timeOfSubstep(5, 2, 3) == clock.timeOfFrame(5));
    CHECK(clock.timeOfSubstep(1, 0, 1) == clock.timeOfFrame(1));
    CHECK(clock.timeOfSubstep(0, 6, 7) == clock.timeOfFrame(0));
}

TEST_CASE("clock rejects bad settings and survives a blow-up", "[clock]") {
    CHECK_THROWS_AS(SimulationClock(0.0, 1.0), eikon::Error);
    CHECK_THROWS_AS(SimulationClock(24.0, -1.0), eikon::Error);
    SimulationClock clock(24.0, 1.0);
    CHECK_THROWS_AS(clock.substepsFor(std::numeric_limits<double>::infinity(), 1.0), eikon::Error);
    CHECK_THROWS_AS(clock.substepsFor(std::nan(""), 1.0), eikon::Error);
    CHECK(clock.substepsFor(1e30, 1.0) == 100000);
}
