#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/, clang-14, ASan + UBSan, in build-fuzz/) and runs each
# on a copy of its seeds. One summary line per target; exits non-zero on any finding (a crash, a
# sanitizer report, a foreign exception, a hang over 20 s, more than 2 GB of memory) and names
# the input that caused it.
#
# Usage: scripts/fuzz.sh [--seconds N | --runs N] [--target NAME]...
#   --seconds N  run each target for N seconds (default 60)
#   --runs N     run each target for N inputs instead (the long runs of RELIABILITY.md)
#   --target T   only this target (fuzz_vdb, fuzz_ply, fuzz_obj, fuzz_off, fuzz_stl, fuzz_scene,
#                fuzz_nrrd);
#                may repeat
#   --resume     start from the working corpus the last run left, not from the seeds (a long run
#                continued after a fix)
# The seed is fixed (-seed=1), so a run is repeatable on the same build. The working corpus and
# findings live under build-fuzz/fuzz/<target>/, never in the repository; a finding goes into the
# normal suite by hand (tests/fuzz/regressions/ and a Catch2 case, see RELIABILITY.md).
set -euo pipefail
cd "$(dirname "$0")/.."

ALL_TARGETS=(fuzz_vdb fuzz_ply fuzz_obj fuzz_off fuzz_stl fuzz_scene fuzz_nrrd)
LIMIT=(-max_total_time=60)
TARGETS=()
RESUME=0
while [ $# -gt 0 ]; do
    case "$1" in
        --seconds) LIMIT=(-max_total_time="$2"); shift 2 ;;
        --runs) LIMIT=(-runs="$2"); shift 2 ;;
        --target) TARGETS+=("$2"); shift 2 ;;
        --resume) RESUME=1; shift ;;
        *) echo "fuzz.sh: unknown argument '$1' (see the usage at the top of the script)" >&2; exit 2 ;;
    esac
done
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=("${ALL_TARGETS[@]}")
for t in "${TARGETS[@]}"; do
    case " ${ALL_TARGETS[*]} " in *" $t "*) ;; *) echo "fuzz.sh: no target '$t'" >&2; exit 2 ;; esac
done

BUILD_DIR=build-fuzz
bash scripts/install-deps.sh
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
    mkdir -p "$BUILD_DIR"
    CC=clang-14 CXX=clang++-14 cmake -S . -B "$BUILD_DIR" -DEIKON_FUZZ=ON \
        -DCMAKE_BUILD_TYPE=Release > "$BUILD_DIR/configure.log" 2>&1 \
        || { cat "$BUILD_DIR/configure.log"; exit 1; }
fi
cmake --build "$BUILD_DIR" -j "$(nproc)" --target "${TARGETS[@]}"

export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Five frames per allocation stack and a 16 MB quarantine instead of 30 and 256 MB: fuzz_vdb
# allocates OpenVDB's node tables on every input and runs twice as fast; a finding's report still
# shows where a block came from. Rerun an input without these for the full stacks.
export ASAN_OPTIONS=malloc_context_size=5:quarantine_size_mb=16
# Library leaks on error paths, each with its reason (tests/fuzz/lsan_suppressions.txt).
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan_suppressions.txt:print_suppressions=0"

# Extra seeds that are not under tests/fuzz/corpus: the inputs of past findings
# (tests/fuzz/regressions), the shipped scenes, and the small files of the shared data folder (big
# ones would slow every mutation down).
extra_seeds() {
    local target="$1" dest="$2" ext="${1#fuzz_}"
    if [ -d "tests/fuzz/regressions/$ext" ]; then cp tests/fuzz/regressions/"$ext"/* "$dest/"; fi
    if [ "$target" = fuzz_scene ]; then
        cp data/scenes/*.json "$dest/"
    elif [ -d ../shared/data ]; then
        find ../shared/data -type f -iname "*.$ext" -size -65k -exec cp {} "$dest/" \;
    fi
}

failed=0
for target in "${TARGETS[@]}"; do
    name="${target#fuzz_}"
    work="$BUILD_DIR/fuzz/$target"
    if [ "$RESUME" = 1 ] && [ -d "$work/corpus" ]; then
        rm -rf "$work/findings" "$work/log.txt"
        mkdir -p "$work/findings"
    else
        rm -rf "$work"
        mkdir -p "$work/corpus" "$work/findings"
        cp tests/fuzz/corpus/"$name"/* "$work/corpus/"
        extra_seeds "$target" "$work/corpus"
    fi
    seeds=$(find "$work/corpus" -type f | wc -l)
    args=(-seed=1 -timeout=20 -rss_limit_mb=2048 "${LIMIT[@]}" -print_final_stats=1
          -artifact_prefix="$work/findings/")
    [ -f "tests/fuzz/$name.dict" ] && args+=(-dict="tests/fuzz/$name.dict")
    set +e
    "$BUILD_DIR/tests/fuzz/$target" "${args[@]}" "$work/corpus" > "$work/log.txt" 2>&1
    rc=$?
    set -e
    # libFuzzer's last status line ("#N DONE cov: C ft: F corp: K/...") and its final stats.
    status=$(grep -E '^#[0-9]+' "$work/log.txt" | tail -1)
    field() { sed -nE "s/.* $1: ([0-9]+).*/\1/p" <<<"$status"; }
    stat() { sed -nE "s/^stat::$1: *([0-9]+).*/\1/p" "$work/log.txt" | tail -1; }
    findings=$(find "$work/findings" -type f | wc -l)
    printf '%-10s  %9s execs  %6s/s  cov %5s  ft %6s  corpus %4s (started from %s)  rss %4s MB  findings %s\n' \
        "$target" "$(stat number_of_executed_units)" "$(stat average_exec_per_sec)" "$(field cov)" \
        "$(field ft)" "$(field corp)" "$seeds" "$(stat peak_rss_mb)" "$findings"
    if [ "$rc" -ne 0 ] || [ "$findings" -gt 0 ]; then
        failed=1
        echo "fuzz.sh: $target found a problem (exit $rc); input: $(find "$work/findings" -type f | head -1)" \
            "; log: $work/log.txt" >&2
        grep -E 'ERROR: |fuzz finding: |runtime error: |Test unit written' "$work/log.txt" | head -5 >&2
    fi
done
exit "$failed"
