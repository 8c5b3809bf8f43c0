// The scan reader, entered where a scene's scan source enters it (core/scene_sources.cpp): the
// NRRD header, then its samples (raw, gzip or ascii, attached) into a float grid, as density and
// through a window.
#include <tbb/global_control.h>

#include "core/scan_layout.h"
#include "core/scan_volume.h"
#include "core/vdb_import.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    static tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    eikon::fuzz::setUpProcess();
    eikon::ensureOpenVdbInitialized();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eikon;
    const std::string& path = fuzz::inputPath(".nrrd");
    fuzz::writeInput(path, data, size);
    fuzz::readExpectingErrors([&] {
        const ScanLayout layout = readNrrdHeader(path);
        fuzz::expectOneLine("the layout", layout.describe());
        readScanVolume(layout, {});
        ScanReadOptions windowed;
        windowed.window = ScanWindow{-100.0, 100.0};
        windowed.fieldName = "temperature";
        readScanVolume(layout, windowed);
    });
    return 0;
}
