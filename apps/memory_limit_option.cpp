#include "apps/memory_limit_option.h"

#include <optional>
#include <string>

#include "core/memory_limit.h"

namespace eikon::app {

void addMemoryLimitOption(CLI::App* command) {
    command
        ->add_option_function<std::string>(
            "--memory-limit",
            [](const std::string& text) {
                const std::optional<double> bytes = parseByteSize(text);
                if (!bytes)
                    throw CLI::ValidationError(
                        "--memory-limit",
                        "expected a size such as 512M, 8G or 8GiB, got \"" + text + "\"");
                setMemoryLimit(*bytes, "--memory-limit");
            },
            "the most memory one scene, cache or grid may plan to take (e.g. 8G; default: 3/4 of "
            "the memory this process may use, or EIKON_MEMORY_LIMIT)")
        ->type_name("SIZE");
}

}  // namespace eikon::app
