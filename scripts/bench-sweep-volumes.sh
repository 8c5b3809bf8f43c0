#!/usr/bin/env bash
# Times the plane sweep (issue 17's measurement) on the shared CT scans at the thesis's viewport
# sizes, beside the photon method on the same volume: for each scan, size and method/backend one
# `eikon render --stats` of data/scenes/ct_tooth.json's materials, light and camera over that scan
# (the scan path and spacing replaced; the scene crops the render volume to the windowed content).
# Prints one markdown row per run: scan, render volume, viewport, method, backend, the method's
# stage ms (with the octree for photons, the only method that needs it), the view's ms, the wall
# time of the whole render (load to PNG) and its peak RSS.
# Usage: scripts/bench-sweep-volumes.sh [SIZES] [RUNS]   e.g. "512 768" 1
#   RUNS > 1 prints each run (take the median yourself: they are interleaved so that a changing
#   load hits every row alike). EIKON=path/to/eikon picks the binary; BACKENDS="cpu gpu" adds
#   the GPU path (llvmpipe here: the software driver's cost, not a GPU's).
#   COMBOS lists method:backend rows; method plane_sweep+interleaved is the plane sweep with the
#   interleaved view ("view": "interleaved": no fluence volume; its "method ms" is the sweep's
#   share of the frame, its "view ms" the rays'). It needs light from the camera's side:
#   LIGHT=front turns the scene's light there for every row (LIGHT=scene keeps ct_tooth.json's,
#   which comes from behind the scan).
set -euo pipefail
cd "$(dirname "$0")/.."
SIZES=${1:-"512 768"}
RUNS=${2:-1}
EIKON=${EIKON:-build/apps/eikon}
BACKENDS=${BACKENDS:-"cpu gpu"}
COMBOS=${COMBOS:-"plane_sweep:cpu plane_sweep:gpu photons:cpu"}
LIGHT=${LIGHT:-scene}
VOLUMES=../shared/data/volumes
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# name file spacing origin
SCANS=(
    "tooth tooth_103x94x161_uint8.raw 0.0125 -0.64,-0.59,-1.0"
    "engine engine_256x256x128_uint8.raw 0.0078125 -1.0,-1.0,-0.5"
)

scene() {  # name file spacing origin method -> path
    local path="$OUT/$1_$5.json"
    /usr/bin/python3 - "$path" "$(realpath "$VOLUMES/$2")" "$3" "$4" "$5" "$OUT" "$LIGHT" <<'PY'
import json, sys
path, scan, spacing, origin, method, out, light = sys.argv[1:8]
scene = json.load(open("data/scenes/ct_tooth.json"))
source = scene["sources"][0]
source["file"] = scan
source["spacing"] = [float(spacing)] * 3
source["origin"] = [float(v) for v in origin.split(",")]
view = "volume"
if method.endswith("+interleaved"):
    method, view = method[: -len("+interleaved")], "interleaved"
scene["render"]["light_transport"] = {"method": method}
if view == "interleaved":
    scene["render"]["light_transport"]["plane_sweep"] = {"view": "interleaved"}
if light == "front":  # from the camera's side (the camera at y = -4.2 looks along +y)
    scene["lights"][0]["direction"] = [-0.5, 0.77, -0.4]
scene["output"] = {"directory": out + "/images", "name": "frame", "png": True, "exr": False}
json.dump(scene, open(path, "w"))
PY
    echo "$path"
}

stage_ms() {  # stats-file stage -> the larger of its cpu and gpu columns (0 when absent)
    awk -v s="$2" '$1 == s && $2 ~ /^[0-9.]+$/ { c = $2 + 0; g = ($3 == "-") ? 0 : $3 + 0;
        v = (c > g ? c : g); exit } END { print v + 0 }' "$1"
}

echo "| scan | volume | viewport | method | backend | method ms | view ms | render s | peak RSS MB |"
echo "|---|---|---|---|---|---:|---:|---:|---:|"
for run in $(seq "$RUNS"); do
    for entry in "${SCANS[@]}"; do
        read -r name file spacing origin <<<"$entry"
        for size in $SIZES; do
            for combo in $COMBOS; do
                method=${combo%%:*}
                backend=${combo##*:}
                [[ " $BACKENDS " == *" $backend "* ]] || continue
                path=$(scene "$name" "$file" "$spacing" "$origin" "$method")
                stats="$OUT/stats.txt"
                /usr/bin/time -f "TIME %e %M" "$EIKON" render "$path" --size "${size}x${size}" \
                    --backend "$backend" --stats --quiet -o "$OUT/frame.png" >"$stats" 2>&1 || {
                    echo "eikon: bench-sweep-volumes: $name $size $method $backend failed:" >&2
                    cat "$stats" >&2
                    exit 1
                }
                volume=$(awk '/^frame 0:/ { print $NF }' "$stats")
                read -r wall rss <<<"$(awk '/^TIME/ { print $2, $3 }' "$stats")"
                # The photons' own stage and the octree only they need.
                method_ms=$(echo "$(stage_ms "$stats" "${method%+*}") + $(stage_ms "$stats" octree)" | bc -l)
                printf "| %s | %s | %s² | %s | %s | %.0f | %.0f | %.2f | %.0f |\n" "$name" \
                    "$volume" "$size" "$method" "$backend" "$method_ms" \
                    "$(stage_ms "$stats" view)" "$wall" "$(echo "$rss / 1024" | bc -l)"
            done
        done
    done
done
