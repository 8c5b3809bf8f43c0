// The --frames grammar (core/frame_list.h): what it accepts, and that everything else is one error
// that shows the grammar (issue 20: `1:3`, `1,3` and `1-3x` used to render the wrong frames).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "core/error.h"
#include "core/frame_list.h"

using namespace eikon;
using Frames = std::vector<int>;

TEST_CASE("frame lists: one frame, a range, a stepped range and comma lists", "[frames]") {
    CHECK(parseFrameList("7") == Frames{7});
    CHECK(parseFrameList("0") == Frames{0});
    CHECK(parseFrameList("1-4") == Frames{1, 2, 3, 4});
    CHECK(parseFrameList("3-3") == Frames{3});
    CHECK(parseFrameList("1-10x3") == Frames{1, 4, 7, 10});
    CHECK(parseFrameList("1-10x2") == Frames{1, 3, 5, 7, 9});
    CHECK(parseFrameList("2-3x5") == Frames{2});
    // Ascending, each once, whatever order and overlap the list has.
    CHECK(parseFrameList("1,3,5-7") == Frames{1, 3, 5, 6, 7});
    CHECK(parseFrameList("9,2,4-5,2,5") == Frames{2, 4, 5, 9});
    CHECK(parseFrameList("2147483647") == Frames{2147483647});
    CHECK(isContiguous(parseFrameList("4-6")));
    CHECK(isContiguous(parseFrameList("6,4,5")));
    CHECK_FALSE(isContiguous(parseFrameList("4,6")));
    CHECK_FALSE(isContiguous(parseFrameList("4-8x2")));
}

TEST_CASE("frame lists: anything else is one error showing the grammar", "[frames]") {
    for (const std::string bad : {"",     "1:3", "1-3x",       "1-3x0",       "1-3y2", "1,",  ",1",
                                  "1,,2", " 1",  "1 ",         "-3",          "+3",    "3-1", "1-",
                                  "x2",   "1.5", "2147483648", "99999999999", "1-2-3", "0x10"}) {
        INFO("'" << bad << "'");
        try {
            parseFrameList(bad);
            FAIL("accepted");
        } catch (const Error& e) {
            CHECK(e.where() == "--frames");
            CHECK_THAT(e.reason(), Catch::Contains("expected frames as 7, 1-10, 1-10x2"));
            CHECK_THAT(e.reason(), Catch::Contains("got '" + bad + "'"));
        }
    }
    // Bounded: a list of more than a million frames is refused before it is made.
    CHECK_THROWS_WITH(parseFrameList("0-2000000000"), Catch::Contains("more than 1000000 frames"));
    CHECK_THROWS_WITH(parseFrameList("0-999999,0-999999x1,1000000"),
                      Catch::Contains("more than 1000000 frames"));
}
