// The scene parser, entered where `eikon render scene.json` enters it: loadScene, which reads
// the file and validates every section. (The command then checks the light-transport section in
// render, which this build leaves out: no GL here.) Files the scene names are not opened by the
// parser; relative ones resolve next to the input.
#include "core/scene.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    eikon::fuzz::setUpProcess();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eikon;
    const std::string& path = fuzz::inputPath(".json");
    fuzz::writeInput(path, data, size);
    fuzz::readExpectingErrors([&] { loadScene(path); });
    return 0;
}
