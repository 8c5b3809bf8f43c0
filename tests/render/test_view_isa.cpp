// The CPU twin's view compiled three times (render/view_pass_cpu.cpp): the AVX2 copy, which runs
// where the processor has AVX2, and the AVX-512 copy, where it has AVX-512 F and VL too, must give
// the baseline x86-64 copy's picture to the bit.
#include <catch2/catch.hpp>

#include "render/view_pass.h"
#include "support/cpu_view_variants.h"

TEST_CASE("the view's AVX2 copy gives the baseline copy's picture, to the bit", "[view][isa]") {
    if (!eikon::viewCpuHasAvx2())
        WARN(
            "no AVX2 copy here (not x86-64 with AVX2, or a sanitizer build): both renders below "
            "run the baseline copy");
    // Dispersion always runs the baseline copy: its case checks that the switch leaves it alone.
    CHECK(eikon::test::casesChangedBySwitch("EIKON_CPU_AVX2") == std::vector<std::string>{});
}

TEST_CASE("the view's AVX-512 copy gives the AVX2 copy's picture, to the bit", "[view][isa]") {
    if (!eikon::viewCpuHasAvx512())
        WARN(
            "no AVX-512 copy here (no AVX-512 F and VL, not x86-64, or a sanitizer build): both "
            "renders below run the same copy");
    CHECK(eikon::test::casesChangedBySwitch("EIKON_CPU_AVX512") == std::vector<std::string>{});
}
