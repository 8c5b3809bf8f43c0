#!/usr/bin/env bash
# Installs dependencies, then configures and builds Eikon (Release, all cores).
# Usage: scripts/build.sh [--sanitize]   (ASan + UBSan build in build-sanitize/)
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR=build
EXTRA=()
if [ "${1:-}" = "--sanitize" ]; then
    BUILD_DIR=build-sanitize
    EXTRA=(-DEIKON_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo)
fi

bash scripts/install-deps.sh
mkdir -p "$BUILD_DIR"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "${EXTRA[@]}" > "$BUILD_DIR/configure.log" 2>&1 \
    || { cat "$BUILD_DIR/configure.log"; exit 1; }
cmake --build "$BUILD_DIR" -j "$(nproc)"
echo "build: $BUILD_DIR/apps/eikon"
