#!/usr/bin/env bash
# Renders every scene in data/scenes/ small, on the CPU twin and on the GPU path (llvmpipe where
# there is no GPU), and prints one line per picture: scene, backend, frame, SHA-256 of the linear
# EXR. A refactor that claims "behaviour does not change" shows it here: the list before and
# after must be equal. tests/scene_hashes.tsv is the committed list; CI checks against it, so a
# later change that moves a picture is visible and has to update the list on purpose.
#
# Usage: scripts/scene-hashes.sh [--eikon PATH] [--backends cpu,gpu] [--scenes a,b]
#                                [--check FILE | --write FILE]
#   --eikon    the binary (default build/apps/eikon)
#   --backends which backends (default cpu,gpu)
#   --scenes   scene names without .json (default: every scene in data/scenes/)
#   --check    compare with FILE; print the lines that differ and exit 1 when any does
#   --write    write the list to FILE (after a deliberate change of pictures; say why in the commit)
# Scenes whose smoke comes from an `eikon simulate` cache are simulated first, for the frames
# rendered only, in a scratch folder (the user's own caches in out/ are never touched).
#
# The CPU twin's pictures are the same bytes on any x86-64 machine (no -march=native, a fixed
# reduction order). The GPU path's depend on the driver and, for llvmpipe, on the vector width
# its JIT picks for the host CPU: the list records the GPU renderer it was made with, and --check
# compares GPU pictures only under that same renderer (saying so when it skips them).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eikon="$root/build/apps/eikon"
backends=cpu,gpu
scenes=""
check=""
write=""
while [ $# -gt 0 ]; do
    case "$1" in
        --eikon) eikon=$(realpath "$2"); shift 2 ;;
        --backends) backends=$2; shift 2 ;;
        --scenes) scenes=$2; shift 2 ;;
        --check) check=$(realpath "$2"); shift 2 ;;
        --write) write=$(realpath -m "$2"); shift 2 ;;
        *) echo "eikon: scene-hashes.sh: unknown option '$1' (see the comment at its top)" >&2; exit 2 ;;
    esac
done
[ -x "$eikon" ] || { echo "eikon: $eikon: no such binary (build first: scripts/build.sh)" >&2; exit 2; }
if [ -z "$scenes" ]; then
    scenes=$(cd "$root/data/scenes" && ls *.json | sed 's/\.json$//' | tr '\n' ',')
fi

# Image size of every picture: small enough for llvmpipe, large enough that a moved caustic or
# shadow edge changes pixels. The volume and photon counts stay the scene's own.
size=48x36
# The frame rendered per scene: the scene's first unless named here. Scenes whose meshes, lights
# or smoke move are taken a few frames in, so that their simulations and tracks are exercised.
frame_of() {
    case "$1" in
        ct_tooth_cut) echo 12 ;;
        glass_blob_poked) echo 6 ;;
        glass_squeezed) echo 6 ;;
        light_circling_glass) echo 6 ;;
        water_pool) echo 4 ;;
        smoke_glass_mesh) echo 3 ;;
        soak_smoke) echo 3 ;;
        *) echo "" ;;
    esac
}

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
out="$scratch/list.tsv"
header="$scratch/header.tsv"
: >"$out"
: >"$header"
gpu_renderer=""
IFS=, read -r -a scene_list <<<"$scenes"
IFS=, read -r -a backend_list <<<"$backends"
for name in "${scene_list[@]}"; do
    [ -n "$name" ] || continue
    scene="$root/data/scenes/$name.json"
    [ -f "$scene" ] || { echo "eikon: $scene: no such scene" >&2; exit 2; }
    # One frame per scene: the one named above, else the scene's first (a cached sequence has only
    # the frames simulated below, and others are an error).
    first=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get('time', {}).get('frame_start', 0))" "$scene")
    frame=$(frame_of "$name")
    frame_args=(--frames "${frame:-$first}")
    # A scene that reads its own simulation cache ("../../out/x_cache" relative to the scene) is
    # copied two folders deep into the scratch folder, so its cache lands in scratch/out/.
    if grep -q '"simulation"' "$scene" && grep -q '"vdb_sequence"' "$scene"; then
        mkdir -p "$scratch/data/scenes"
        cp "$scene" "$scratch/data/scenes/$name.json"
        scene="$scratch/data/scenes/$name.json"
        (cd "$scratch" && "$eikon" simulate "$scene" --frames "${frame:-$first}" \
            >"$scratch/log" 2>&1) || { cat "$scratch/log" >&2; exit 1; }
    fi
    for backend in "${backend_list[@]}"; do
        dir="$scratch/$name.$backend"
        # The EXR only, numbered whether the scene has one frame or many.
        (cd "$scratch" && "$eikon" render "$scene" --backend "$backend" --size "$size" \
            -o "$dir/frame_####.exr" "${frame_args[@]}" >"$scratch/log" 2>&1) ||
            { cat "$scratch/log" >&2; exit 1; }
        # `eikon render` names the backend it renders with: "GPU: <renderer, version>".
        if [ "$backend" = gpu ] && [ -z "$gpu_renderer" ]; then
            gpu_renderer=$(grep -m 1 '^GPU: ' "$scratch/log" || true)
            printf '# gpu\t%s\n' "$gpu_renderer" >>"$header"
        fi
        exr=$(ls "$dir"/*.exr | head -n 1)
        f=$(basename "$exr" .exr)
        printf '%s\t%s\t%s\t%s\n' "$name" "$backend" "${f##*_}" \
            "$(sha256sum "$exr" | cut -d' ' -f1)" | tee -a "$out"
    done
done

if [ -n "$write" ]; then
    cat "$header" "$out" >"$write"
    echo "scene-hashes: wrote $(wc -l <"$out") hashes to $write"
fi
if [ -n "$check" ]; then
    # Only the scenes and backends rendered now are compared; GPU pictures only under the GPU
    # renderer the list was made with.
    listed_renderer=$(grep -P '^# gpu\t' "$check" | cut -f2- || true)
    if [ -n "$gpu_renderer" ] && [ "$gpu_renderer" != "$listed_renderer" ]; then
        echo "scene-hashes: GPU pictures not compared: this GPU is '$gpu_renderer', the list's" \
            "'$listed_renderer'"
        grep -v -P '^[^\t]+\tgpu\t' "$out" >"$scratch/cpu_only.tsv" || true
        mv "$scratch/cpu_only.tsv" "$out"
    fi
    expected="$scratch/expected.tsv"
    : >"$expected"
    while IFS=$'\t' read -r s b f h; do
        case "$s" in "#"*) continue ;; esac
        grep -q "^$s	$b	" "$out" && printf '%s\t%s\t%s\t%s\n' "$s" "$b" "$f" "$h" >>"$expected"
    done <"$check"
    if ! diff <(sort "$expected") <(sort "$out") >"$scratch/diff"; then
        echo "eikon: scene-hashes: pictures differ from $check ('<' expected, '>' now):" >&2
        grep '^[<>]' "$scratch/diff" >&2
        exit 1
    fi
    echo "scene-hashes: $(wc -l <"$out") pictures equal to $check"
fi
