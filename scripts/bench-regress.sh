#!/usr/bin/env bash
# What `eikon regress` costs over rendering its cases alone, and what -j 2 gives over -j 1: a
# suite of 20 cases (5 example scenes x 4 image sizes, CPU twin, PNG by hash) built in a temporary
# folder, its references written with --update, then
#   1. the 20 renders run one after another by hand (the same command lines regress runs),
#   2. eikon regress -j 1,  3. eikon regress -j 2,
# each the median of --reps runs (default 3). Prints a table for BENCHMARKS.md.
# Usage: scripts/bench-regress.sh [--eikon build/apps/eikon] [--reps 3]
set -euo pipefail
cd "$(dirname "$0")/.."
EIKON=build/apps/eikon
REPS=3
while [ $# -gt 0 ]; do
    case "$1" in
        --eikon) EIKON="$2"; shift 2 ;;
        --reps) REPS="$2"; shift 2 ;;
        *) echo "bench-regress.sh: unknown argument '$1'" >&2; exit 2 ;;
    esac
done
[ -x "$EIKON" ] || { echo "bench-regress.sh: no eikon at $EIKON (build first)" >&2; exit 1; }
EIKON=$(realpath "$EIKON")
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
SUITE="$TMP/suite"
mkdir -p "$SUITE" "$TMP/direct"
SCENES=(homogeneous_cube glass_sphere_fog fog_sphere_spot luneburg_lens mirage_slab)
SIZES=(64x48 96x72 128x96 160x120)
for scene in "${SCENES[@]}"; do
    for size in "${SIZES[@]}"; do
        printf '{"input": "%s", "size": "%s", "compare": {"png": "hash"}}\n' \
            "$PWD/data/scenes/$scene.json" "$size" > "$SUITE/${scene}_$size.json"
    done
done
"$EIKON" regress "$SUITE" --update -j 2 > /dev/null

median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" > /dev/null; t1=$(date +%s.%N); awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.3f", a / b}'; }
direct() {
    for scene in "${SCENES[@]}"; do
        for size in "${SIZES[@]}"; do
            "$EIKON" render "$PWD/data/scenes/$scene.json" -o "$TMP/direct/frame_####.png" \
                --backend cpu --quiet --size "$size" \
                --stats-json "$TMP/direct/render_stats.json" > /dev/null
        done
    done
}
declare -A T
for what in direct j1 j2; do
    for ((r = 0; r < REPS; r++)); do
        case $what in
            direct) seconds direct ;;
            j1) seconds "$EIKON" regress "$SUITE" -j 1 ;;
            j2) seconds "$EIKON" regress "$SUITE" -j 2 ;;
        esac
    done | median > "$TMP/$what.txt"
    T[$what]=$(cat "$TMP/$what.txt")
done
echo "| run (20 cases, CPU twin, PNG by hash; median of $REPS) | seconds | against the renders alone |"
echo "|---|---|---|"
printf '| the 20 renders by hand, one after another | %.2f | 1.00 |\n' "${T[direct]}"
printf '| eikon regress -j 1 | %.2f | %.3f |\n' "${T[j1]}" "$(ratio "${T[j1]}" "${T[direct]}")"
printf '| eikon regress -j 2 | %.2f | %.3f |\n' "${T[j2]}" "$(ratio "${T[j2]}" "${T[direct]}")"
