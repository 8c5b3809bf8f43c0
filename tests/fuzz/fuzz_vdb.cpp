// The VDB reader, entered where the command line enters it: `eikon info cache.vdb` (inspectVdb,
// then the text it prints) and `eikon render cache.vdb` or a scene's VDB source (importVdb into
// the fields).
#include <tbb/global_control.h>

#include "core/field_registry.h"
#include "core/vdb_import.h"
#include "core/vdb_info.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // One thread: OpenVDB's reductions (active voxel count and bounds) start TBB workers whose
    // spinning, under ASan and on a busy machine, cost more than the work; inputs are tiny.
    static tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    eikon::fuzz::setUpProcess();
    eikon::ensureOpenVdbInitialized();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eikon;
    const std::string& path = fuzz::inputPath(".vdb");
    fuzz::writeInput(path, data, size);
    fuzz::readExpectingErrors(
        [&] { fuzz::expectPrintableLines("eikon info's text", formatVdbInfo(inspectVdb(path))); });
    fuzz::readExpectingErrors([&] {
        FieldRegistry fields;
        importVdb(path, fields);
    });
    return 0;
}
