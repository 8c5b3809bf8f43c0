#!/usr/bin/env bash
# Installs dependencies, builds, and renders the Houdini smoke cache with the GPU viewing pass
# (headless: EGL surfaceless, Mesa llvmpipe where there is no GPU).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/build.sh
mkdir -p out
# --backend gpu: the compute shaders, even on llvmpipe (the default would pick the faster CPU twin).
./build/apps/eikon render ../shared/data/vdb/houdini_smoke1.vdb -o out/ --stats --backend gpu
