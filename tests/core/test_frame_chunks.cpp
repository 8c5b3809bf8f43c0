// Farm arithmetic (issue 21): the chunks of a frame list cover it exactly once, contiguous and as
// even as possible, for uneven ranges, more chunks than frames and stepped lists; `--chunk` text
// and a Slurm job array's environment; and SHA-256 against FIPS 180-4's vectors and sha256sum.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

#include "core/error.h"
#include "core/frame_chunks.h"
#include "core/frame_list.h"
#include "core/sha256.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

std::function<const char*(const char*)> envOf(const std::map<std::string, std::string>& vars) {
    return [vars](const char* name) -> const char* {
        const auto it = vars.find(name);
        return it == vars.end() ? nullptr : it->second.c_str();
    };
}

const auto kNoEnv = envOf({});

}  // namespace

TEST_CASE("chunks cover the frames once, contiguous and even", "[farm]") {
    struct Case {
        const char* frames;
        int chunks;
    };
    for (const Case& c : {Case{"1-8", 3}, Case{"1-240", 7}, Case{"1-3", 5}, Case{"7", 4},
                          Case{"1-20x3", 4}, Case{"1,3,5-9,20", 3}, Case{"0-999", 1000}}) {
        const std::vector<int> all = parseFrameList(c.frames);
        std::vector<int> joined;
        size_t smallest = all.size(), largest = 0;
        for (int k = 1; k <= c.chunks; ++k) {
            const std::vector<int> mine = framesOfChunk(all, {k, c.chunks});
            joined.insert(joined.end(), mine.begin(), mine.end());
            smallest = std::min(smallest, mine.size());
            largest = std::max(largest, mine.size());
        }
        INFO(c.frames << " in " << c.chunks);
        CHECK(joined == all);  // in order, each once: contiguous runs of the list
        CHECK(largest - smallest <= 1);
    }
    const std::vector<int> eight = parseFrameList("1-8");
    CHECK(framesOfChunk(eight, {1, 3}) == std::vector<int>{1, 2});
    CHECK(framesOfChunk(eight, {2, 3}) == std::vector<int>{3, 4, 5});
    CHECK(framesOfChunk(eight, {3, 3}) == std::vector<int>{6, 7, 8});
    CHECK(framesOfChunk(parseFrameList("1-20x3"), {2, 3}) == std::vector<int>{7, 10});
    CHECK(describeChunk(eight, {2, 3}) == "chunk 2/3: frames 3-5 (3 of 8)");
    CHECK(describeChunk(parseFrameList("1-3"), {1, 5}) ==
          "chunk 1/5: no frames (5 chunks of 3 frames)");
    CHECK(describeChunk(parseFrameList("1-3"), {4, 5}) == "chunk 4/5: frame 2 (1 of 3)");
    CHECK(describeChunk(parseFrameList("1-20x3"), {2, 3}) == "chunk 2/3: frames 7..10 (2 of 7)");
}

TEST_CASE("the chunk option takes K/N or a Slurm job array's task", "[farm]") {
    const FrameChunk c = parseFrameChunk("2/3", kNoEnv);
    CHECK(c.index == 2);
    CHECK(c.count == 3);
    for (const char* bad : {"0/3", "4/3", "3", "/3", "2/", "2/0", "a/b", "2/3/4", "-1/3", "1 /3",
                            "2/3x", "auto2", ""}) {
        INFO(bad);
        CHECK_THROWS_WITH(parseFrameChunk(bad, kNoEnv),
                          Catch::StartsWith("--chunk: expected K/N") && Catch::Contains("auto"));
    }
    // sbatch --array=0-2: ids 0, 1, 2 are chunks 1, 2, 3 of 3.
    auto task = [](const char* id, const char* count, const char* min, const char* step) {
        std::map<std::string, std::string> vars{{"SLURM_ARRAY_TASK_ID", id},
                                                {"SLURM_ARRAY_TASK_COUNT", count}};
        if (min) vars["SLURM_ARRAY_TASK_MIN"] = min;
        if (step) vars["SLURM_ARRAY_TASK_STEP"] = step;
        return envOf(vars);
    };
    CHECK(parseFrameChunk("auto", task("0", "3", "0", nullptr)).index == 1);
    CHECK(parseFrameChunk("auto", task("2", "3", "0", nullptr)).index == 3);
    // --array=1-3 and --array=10-14:2 (ids 10, 12, 14).
    CHECK(parseFrameChunk("auto", task("1", "3", "1", nullptr)).index == 1);
    const FrameChunk stepped = parseFrameChunk("auto", task("12", "3", "10", "2"));
    CHECK(stepped.index == 2);
    CHECK(stepped.count == 3);
    CHECK_THROWS_WITH(parseFrameChunk("auto", kNoEnv),
                      Catch::Contains("SLURM_ARRAY_TASK_ID, which is not set"));
    CHECK_THROWS_WITH(parseFrameChunk("auto", task("5", "3", "0", nullptr)),
                      Catch::Contains("not one of the 3 tasks"));
    CHECK_THROWS_WITH(parseFrameChunk("auto", task("x", "3", "0", nullptr)),
                      Catch::Contains("SLURM_ARRAY_TASK_ID is 'x', not a whole number"));
}

TEST_CASE("SHA-256 gives FIPS 180-4's digests and sha256sum's", "[farm]") {
    CHECK(sha256Hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha256Hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    CHECK(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
          "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    Sha256 million;
    const std::string tenA(1000, 'a');
    for (int i = 0; i < 1000; ++i) million.update(tenA);
    CHECK(million.hexDigest() ==
          "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
    // A file against the system's sha256sum, across block and padding boundaries.
    const std::string dir = test::scratchDir("sha256_file");
    std::string bytes;
    for (int i = 0; i < 200003; ++i) bytes += char((i * 7919) & 0xff);
    const std::string path = dir + "/bytes.bin";
    { std::ofstream(path, std::ios::binary) << bytes; }
    const std::string command = "sha256sum '" + path + "' > '" + dir + "/sum.txt'";
    REQUIRE(std::system(command.c_str()) == 0);
    std::ifstream sum(dir + "/sum.txt");
    std::string expected;
    sum >> expected;
    CHECK(sha256OfFile(path) == expected);
    CHECK(sha256Hex(bytes) == expected);
    CHECK_THROWS_WITH(sha256OfFile(dir + "/none.bin"),
                      Catch::StartsWith(dir + "/none.bin: cannot read"));
}
