// A mesh reader, entered where `eikon info mesh.<ext>` enters it: loadMesh, the topology report
// and the text it prints. One source for the four formats: the build names the extension
// (EIKON_FUZZ_MESH_EXTENSION, tests/fuzz/CMakeLists.txt), and loadMesh picks the reader by it.
#include "fuzz_input.h"
#include "sim/mesh_check.h"
#include "sim/mesh_info.h"
#include "sim/mesh_io.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    eikon::fuzz::setUpProcess();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eikon;
    const std::string& path = fuzz::inputPath(EIKON_FUZZ_MESH_EXTENSION);
    fuzz::writeInput(path, data, size);
    fuzz::readExpectingErrors([&] {
        const LoadedMesh loaded = loadMesh(path);
        fuzz::expectPrintableLines("eikon info's text",
                                   formatMeshInfo(path, loaded, checkMesh(loaded)));
    });
    return 0;
}
