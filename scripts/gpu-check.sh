#!/usr/bin/env bash
# The GPU path on a hardware GPU (issue 18, "ready for hardware GPUs"): which OpenGL renderer
# eikon gets with no display (EGL: hardware devices first, render/gl_context.cpp), the
# GPU-against-CPU-twin tests (eikon_tests_render "[gpu]"), and the relighting stages of
# data/scenes/glass_sphere_fog.json timed on both backends at 64³ / 128² photons / 320×240 and
# Sun et al.'s 128³ / 1024² photons / 640×480. Writes OUT/report.md and prints it.
#
# Usage:
#   scripts/gpu-check.sh [--build DIR] [--runs N] [--out DIR] [--allow-software]
#       with a build here (built by scripts/build.sh when DIR has none; default build/)
#   scripts/gpu-check.sh --bundle FILE.tar.xz [--build DIR]
#       packs the build's eikon and eikon_tests_render, stripped, with the shared libraries they
#       need except the C library and the OpenGL driver's, for a machine with no package archive
#       (glibc 2.36 or newer there: Debian 12's). glvnd's libEGL/libOpenGL go in lib/glvnd and
#       are used only where the machine has none.
#   scripts/gpu-check.sh --from-bundle FILE.tar.xz [--runs N] [--out DIR] [--allow-software]
#       on that machine, from a copy of this repository (shaders and scenes are read from it)
#
# A software rasterizer (llvmpipe) is refused unless --allow-software: figures from it are not a
# GPU's. Where the NVIDIA driver's EGL library is installed but glvnd has no vendor file for it
# (a container given the GPU without its graphics files), the check writes one and points glvnd
# at it (__EGL_VENDOR_LIBRARY_FILENAMES).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

build=build
runs=3
out=gpu-check
allow_software=0
bundle=""
from_bundle=""
fail() {
    echo "eikon: gpu-check: $*" >&2
    exit 1
}
while [ $# -gt 0 ]; do
    case "$1" in
        --build) build=${2:?}; shift 2 ;;
        --runs) runs=${2:?}; shift 2 ;;
        --out) out=${2:?}; shift 2 ;;
        --allow-software) allow_software=1; shift ;;
        --bundle) bundle=${2:?}; shift 2 ;;
        --from-bundle) from_bundle=${2:?}; shift 2 ;;
        -h | --help) sed -n '2,23p' "$0"; exit 0 ;;
        *) fail "unknown argument '$1' (see --help)" ;;
    esac
done
[[ "$runs" =~ ^[1-9][0-9]?$ ]] || fail "--runs: '$runs' is not a number from 1 to 99"

# Libraries the target machine brings itself: the C library and the OpenGL driver stack.
system_library() {
    case "$1" in
        libc.so* | libm.so* | libpthread.so* | libdl.so* | librt.so* | ld-linux* | \
            libEGL* | libGL* | libOpenGL* | libGLX* | libGLdispatch* | libnvidia* | libcuda*)
            return 0 ;;
    esac
    return 1
}

# Whether the dynamic linker's cache has library NAME (a string test: `ldconfig -p | grep -q`
# would fail under pipefail when grep stops reading early).
has_library() {
    local cache
    cache=$(/sbin/ldconfig -p)
    [[ "$cache" == *"$1 "* ]]
}

make_bundle() {
    local eikon="$build/apps/eikon" tests="$build/tests/eikon_tests_render"
    [ -x "$eikon" ] && [ -x "$tests" ] || bash scripts/build.sh
    local work
    work=$(mktemp -d)
    local stage="$work/eikon-gpu-check"
    mkdir -p "$stage/bin" "$stage/lib/glvnd"
    cp "$eikon" "$tests" "$stage/bin/"
    strip --strip-unneeded "$stage/bin/"*
    ldd "$eikon" "$tests" | awk '/=> \// {print $3}' | sort -u | while read -r lib; do
        system_library "$(basename "$lib")" || cp -L "$lib" "$stage/lib/"
    done
    for lib in libEGL.so.1 libOpenGL.so.0 libGLdispatch.so.0; do
        path=$(/sbin/ldconfig -p | awk -v n="$lib" '$1 == n && !found {print $NF; found = 1}')
        [ -n "$path" ] && cp -L "$path" "$stage/lib/glvnd/"
    done
    git rev-parse HEAD >"$stage/COMMIT" 2>/dev/null || echo unknown >"$stage/COMMIT"
    mkdir -p "$(dirname "$bundle")"
    tar -C "$work" -cJf "$bundle" eikon-gpu-check
    echo "wrote $bundle ($(du -h "$bundle" | cut -f1), built at commit $(cat "$stage/COMMIT"))"
    rm -rf "$work"
}

if [ -n "$bundle" ]; then
    make_bundle
    exit 0
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
if [ -n "$from_bundle" ]; then
    [ -f "$from_bundle" ] || fail "--from-bundle: no such file '$from_bundle'"
    rm -rf "$out/bundle" && mkdir -p "$out/bundle"
    tar -C "$out/bundle" -xJf "$from_bundle" || fail "--from-bundle: '$from_bundle' is not a bundle"
    base="$out/bundle/eikon-gpu-check"
    eikon="$base/bin/eikon"
    tests="$base/bin/eikon_tests_render"
    libs="$base/lib"
    has_library libEGL.so.1 || libs="$libs:$base/lib/glvnd"
    export LD_LIBRARY_PATH="$libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    commit=$(cat "$base/COMMIT")
else
    eikon="$build/apps/eikon"
    tests="$build/tests/eikon_tests_render"
    [ -x "$eikon" ] && [ -x "$tests" ] || bash scripts/build.sh
    commit=$(git rev-parse HEAD 2>/dev/null || echo unknown)
fi
# Shaders, scenes and test data from this copy of the repository, not the build's paths.
export EIKON_SHADER_DIR="$root/shaders"
export EIKON_TEST_SOURCE_DIR="$root"
export EIKON_TEST_SCRATCH_DIR="$out/scratch"
[ -d "$root/../shared/data" ] && export EIKON_TEST_SHARED_DATA="$root/../shared/data"

# glvnd finds a driver through its vendor files; a GPU container may lack NVIDIA's.
if ! ls /usr/share/glvnd/egl_vendor.d/*nvidia* >/dev/null 2>&1 && has_library libEGL_nvidia.so.0; then
    printf '{"file_format_version": "1.0.0", "ICD": {"library_path": "libEGL_nvidia.so.0"}}\n' \
        >"$out/10_nvidia.json"
    export __EGL_VENDOR_LIBRARY_FILENAMES="$out/10_nvidia.json"
fi

report="$out/report.md"
log="$out/log.txt"
: >"$log"

# 1. The renderer eikon's GPU path gets.
probe=$("$eikon" render data/scenes/homogeneous_cube.json --backend gpu --size 32x32 \
    -o "$out/probe/frame.exr" 2>&1) || fail "the GPU path does not start: $(echo "$probe" | tail -n 3)"
renderer=$(awk '/^GPU: / && !found {sub(/^GPU: /, ""); print; found = 1}' <<<"$probe")
case "$renderer" in
    *llvmpipe* | *softpipe* | *swrast*)
        [ "$allow_software" = 1 ] ||
            fail "the GPU path runs on '$renderer', a software rasterizer: no hardware GPU answered through EGL (NVIDIA: is libEGL_nvidia.so.0 installed? --allow-software checks it anyway)" ;;
esac
gpu_name=$(command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>/dev/null | head -n 1 || true)

# 2. GPU against the CPU twin.
echo "== tests: eikon_tests_render [gpu]" >>"$log"
tests_status=0
"$tests" "[gpu]" >>"$log" 2>&1 || tests_status=$?
tests_line=$(grep -E "^(All tests passed|test cases:)" "$log" | tail -n 1 || true)

# 3. The stages, on both backends, RUNS runs each.
variant() { # resolution per_side width height -> scene path (sed: the machine may lack Python)
    local path="$out/scenes/glass_${1}_${2}_${3}x${4}.json"
    mkdir -p "$out/scenes"
    sed -e "s/\"resolution\": *[0-9]*/\"resolution\": $1/" \
        -e "s/\"render\": *{[^}]*}/\"render\": { \"width\": $3, \"height\": $4, \"light_transport\": { \"photons\": { \"per_side\": $2 } } }/" \
        -e "s|\"output\": *{[^}]*}|\"output\": { \"directory\": \"$path.out\", \"name\": \"frame\", \"png\": true, \"exr\": false }|" \
        data/scenes/glass_sphere_fog.json >"$path"
    grep -q "\"per_side\": $2" "$path" || fail "could not make the $1³ variant of glass_sphere_fog.json"
    echo "$path"
}
timings="$out/timings.tsv" # size, backend, run, stage, cpu ms, gpu ms ("-": none)
: >"$timings"
for size in "64 128 320 240" "128 1024 640 480"; do
    read -r res side w h <<<"$size"
    scene=$(variant $size)
    for backend in gpu cpu; do
        for run in $(seq 1 "$runs"); do
            echo "== $res^3 / $side^2 photons / ${w}x$h, $backend, run $run" | tee -a "$log" >&2
            "$eikon" render "$scene" --backend "$backend" --stats >"$out/run.txt" 2>&1 ||
                fail "eikon render failed: $(tail -n 3 "$out/run.txt")"
            cat "$out/run.txt" >>"$log"
            # The --stats table: "  stage  cpu-ms  gpu-ms" ("-" where a backend has none).
            awk -v size="${res}³/${side}²/${w}x$h" -v backend="$backend" -v run="$run" '
                /^  stage / {table = 1; next}
                table && NF == 3 && $2 ~ /^[0-9.]+$/ {
                    print size "\t" backend "\t" run "\t" $1 "\t" $2 "\t" $3
                }
                table && NF != 3 {table = 0}' "$out/run.txt" >>"$timings"
        done
    done
done

# The median of column `col` of the rows of (size, backend, stage); "-" when it has no numbers.
median() {
    awk -F'\t' -v s="$1" -v b="$2" -v t="$3" -v col="$4" \
        '$1 == s && $2 == b && $4 == t && $col ~ /^[0-9.]+$/ {print $col}' "$timings" | sort -n |
        awk '{v[NR] = $1} END {if (!NR) print "-"; else print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2)}'
}
{
    echo "# GPU check, $(date -u +%Y-%m-%d)"
    echo
    echo "- commit: $commit"
    echo "- OpenGL renderer: $renderer"
    [ -n "$gpu_name" ] && echo "- nvidia-smi: $gpu_name"
    echo "- CPU: $(nproc) cores, $(grep -m 1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
    echo "- GPU against the CPU twin (eikon_tests_render \"[gpu]\"): ${tests_line:-no summary} (exit $tests_status)"
    echo "- stages: data/scenes/glass_sphere_fog.json, medians of $runs runs, ms. GPU backend: the"
    echo "  CPU's wall time in the stage (submission, waits) and the GPU timer queries' time; the"
    echo "  ratio is the CPU twin's over the larger of the two."
    for size in $(cut -f1 "$timings" | awk '!seen[$0]++'); do
        echo
        echo "| $size | CPU twin | GPU backend, wall | GPU timer | CPU twin / GPU |"
        echo "|---|---:|---:|---:|---:|"
        for stage in $(awk -F'\t' -v s="$size" '$1 == s {print $4}' "$timings" | awk '!seen[$0]++'); do
            c=$(median "$size" cpu "$stage" 5)
            gw=$(median "$size" gpu "$stage" 5)
            gt=$(median "$size" gpu "$stage" 6)
            ratio=$(awk -v c="$c" -v a="$gw" -v b="$gt" 'BEGIN {
                g = (a + 0 > b + 0) ? a + 0 : b + 0
                if (c != "-" && g > 0) printf "%.1f", c / g; else print "-" }')
            echo "| $stage | $c | $gw | $gt | $ratio |"
        done
    done
    echo
    echo "Every run's output: $log"
} >"$report"
cat "$report"
[ "$tests_status" = 0 ] || fail "GPU against the CPU twin failed (exit $tests_status): see $log"
