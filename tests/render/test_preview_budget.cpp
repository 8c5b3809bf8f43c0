// budgetedPreviewScale (render/preview_budget.h): the viewer's preview scale from a frame budget.
// A frame is a size-independent part plus a viewing pass that goes with the pixel count; the
// scale chosen is the finest whose predicted frame fits the budget.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/preview_budget.h"

using eikon::budgetedPreviewScale;
using eikon::kMaxPreviewScale;

TEST_CASE("the preview scale is the finest whose predicted frame fits the budget",
          "[preview_budget]") {
    // At 1/4: 10 ms fixed + 20 ms of viewing. At 1/2 the view costs 80 ms, at full size 320 ms.
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, 1000.0) == 1);  // 330 ≤ 800
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, 100.0) == 4);   // 1/2: 90 > 0.8·100; 1/4: 30
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, 120.0) == 2);   // 90 ≤ 96
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, 30.0) == 4);    // the budget exactly: kept
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, 20.0) == 8);    // 10 + 5 ≤ 20
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, 12.0) == 16);   // 10 + 1.25 ≤ 12
    // The size-independent part alone is over the budget: nothing fits, the coarsest.
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, 5.0) == kMaxPreviewScale);
    // From the coarsest, a fast frame goes finer in one choice, not one level at a time.
    CHECK(budgetedPreviewScale(16, 2.0, 1.0, 1000.0) == 1);  // 1 + 256 ≤ 800
}

TEST_CASE("a finer preview needs a margin under the budget, a coarser one none",
          "[preview_budget]") {
    // At 1/2: 0 fixed, 40 ms viewing; full size predicts 160 ms.
    CHECK(budgetedPreviewScale(2, 40.0, 40.0, 160.0) == 2);  // 160 > 0.8·160: stays
    CHECK(budgetedPreviewScale(2, 40.0, 40.0, 200.0) == 1);  // 160 ≤ 0.8·200
    // Over the budget at the current scale: coarser as soon as a coarser one fits.
    CHECK(budgetedPreviewScale(2, 40.0, 40.0, 39.0) == 4);
}

TEST_CASE("no budget, or times that are not numbers, keep the scale", "[preview_budget]") {
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, 0.0) == 4);
    CHECK(budgetedPreviewScale(4, 30.0, 20.0, -1.0) == 4);
    CHECK(budgetedPreviewScale(8, NAN, 20.0, 100.0) == 8);
    CHECK(budgetedPreviewScale(8, 30.0, INFINITY, 100.0) == 8);
    CHECK(budgetedPreviewScale(2, 30.0, 20.0, INFINITY) == 2);
    // A view time above the frame's (clock noise) is read as the whole frame.
    CHECK(budgetedPreviewScale(4, 30.0, 50.0, 1000.0) == 1);  // 0 + 480 ≤ 800
}
