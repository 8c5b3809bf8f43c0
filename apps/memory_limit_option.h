#pragma once
// --memory-limit on the commands that read scenes and caches: replaces eikon's memory limit
// (core/memory_limit.h) before the command runs.
#include <CLI/CLI.hpp>

namespace eikon::app {

void addMemoryLimitOption(CLI::App* command);

}  // namespace eikon::app
