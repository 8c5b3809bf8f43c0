#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "render/image.h"

namespace eikon::app {

void addDiffCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("diff", "Compare a linear EXR image with a reference EXR");
    auto test = std::make_shared<std::string>();
    auto reference = std::make_shared<std::string>();
    cmd->add_option("test", *test, "EXR to judge")->required();
    cmd->add_option("reference", *reference, "reference EXR")->required();
    cmd->footer(
        "Example (from the repository root):\n  eikon render data/scenes/homogeneous_cube.json -o "
        "out/a.exr --backend gpu && eikon render data/scenes/homogeneous_cube.json -o out/b.exr "
        "--backend cpu && eikon diff out/a.exr out/b.exr\n");
    cmd->callback([test, reference, &exitCode] {
        const ImageDifference d = compareImages(readExr(*test), readExr(*reference));
        std::printf("rmse %.6g  max_abs %.6g  reference_max %.6g  mean_relative %.6g\n", d.rmse,
                    d.maxAbs, d.referenceMax, d.meanRelative);
        exitCode = 0;
    });
}

}  // namespace eikon::app
