#!/usr/bin/env bash
# The time to a first GPU frame on Mesa's llvmpipe with a cold shader cache, where compiling the
# shaders is most of it: each scene rendered by `eikon render --backend gpu` at a small size,
# RUNS processes with Mesa's on-disk shader cache disabled (every shader compiled, as on a fresh
# machine or after a shader change) and RUNS with it warm (the same sources compiled before).
# Prints one markdown row per scene: the median wall-clock seconds of each, and their difference
# (the compile time). llvmpipe compiles with LLVM, and a shader compiler inlines every call:
# see the comment on integrateViewRay in shaders/shared/view_march.h.
# Usage: scripts/bench-shader-compile.sh [RUNS] [SCENES]
#        e.g. 3 "data/scenes/fog_sphere_spot.json data/scenes/glass_sphere_floor.json"
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${1:-3}
SCENES=${2:-"data/scenes/fog_sphere_spot.json data/scenes/glass_sphere_floor.json"}
EIKON=${EIKON:-build/apps/eikon}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# Seconds one render takes; "$@" is the environment to run it in.
render_seconds() {
    local scene=$1
    shift
    local start end
    start=$(date +%s.%N)
    env "$@" "$EIKON" render "$scene" --backend gpu --size 48x36 --quiet -o "$OUT/frame.png" \
        >"$OUT/log.txt" 2>&1 || {
        echo "eikon: bench-shader-compile: $scene failed:" >&2
        cat "$OUT/log.txt" >&2
        exit 1
    }
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN {print b - a}'
}

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

echo "| scene | cold cache s (median of $RUNS) | warm cache s | compiling s |"
echo "|---|---:|---:|---:|"
for scene in $SCENES; do
    render_seconds "$scene" >/dev/null  # fills the cache for the warm runs
    cold=$(for _ in $(seq "$RUNS"); do render_seconds "$scene" MESA_SHADER_CACHE_DISABLE=true; done | median)
    warm=$(for _ in $(seq "$RUNS"); do render_seconds "$scene" MESA_SHADER_CACHE_DISABLE=false; done | median)
    awk -v s="$(basename "$scene")" -v c="$cold" -v w="$warm" \
        'BEGIN {printf "| %s | %.1f | %.1f | %.1f |\n", s, c, w, c - w}'
done
