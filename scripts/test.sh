#!/usr/bin/env bash
# Installs dependencies, builds, and runs every test (Catch2 through ctest).
# Usage: scripts/test.sh [--sanitize]   (the same suite under AddressSanitizer + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/build.sh "$@"
BUILD_DIR=build
if [ "${1:-}" = "--sanitize" ]; then
    BUILD_DIR=build-sanitize
    # Mesa's llvmpipe keeps allocations alive until exit by design; leak reports from it are noise.
    export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fi
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)"
