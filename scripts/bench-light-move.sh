#!/usr/bin/env bash
# The time to a new image after a light move, per light-transport method (issue 17's "a light
# move" measurement): data/scenes/light_circling_glass.json, whose spot light circles the glass
# frame by frame over a floor receiver, rendered frames 0..N with each method on the CPU twin.
# From frame 1 on only the light stage and the view pass rerun (the fields, ∇n and the octree
# are cached), so each later frame is a light move. Prints one markdown row per method: the
# first frame's light stage (with the octree for photons), then over frames 1..N the median light
# stage, the median view pass and the median of their sum.
# Usage: scripts/bench-light-move.sh [FRAMES] [SIZE] [METHODS]   e.g. 8 320x240 "photons plane_sweep"
set -euo pipefail
cd "$(dirname "$0")/.."
FRAMES=${1:-8}
SIZE=${2:-320x240}
METHODS=${3:-"photons plane_sweep light_volumes"}
EIKON=${EIKON:-build/apps/eikon}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

echo "| method | frame 0 light ms | light ms (median, frames 1-$FRAMES) | view ms | light + view ms |"
echo "|---|---:|---:|---:|---:|"
for method in $METHODS; do
    scene="$OUT/$method.json"
    /usr/bin/python3 - "$method" "$scene" "$OUT" <<'PY'
import json, sys
method, path, out = sys.argv[1:4]
scene = json.load(open("data/scenes/light_circling_glass.json"))
scene.setdefault("render", {})["light_transport"] = {"method": method}
scene["output"] = {"directory": out + "/images", "name": "frame", "png": True, "exr": False}
json.dump(scene, open(path, "w"))
PY
    # The light stage is named after the method ("light" for light volumes).
    stage=$method
    [[ $method == light_volumes ]] && stage=light
    "$EIKON" render "$scene" --frames "0-$FRAMES" --size "$SIZE" --backend cpu --stats --quiet \
        -o "$OUT/images/" >"$OUT/stats.txt" 2>&1 || {
        echo "eikon: bench-light-move: $method failed:" >&2
        cat "$OUT/stats.txt" >&2
        exit 1
    }
    /usr/bin/python3 - "$OUT/stats.txt" "$method" "$stage" <<'PY'
import statistics, sys
path, method, stage = sys.argv[1:4]
frames, current = [], None
for line in open(path):
    words = line.split()
    if line.startswith("frame "):
        current = {}
        frames.append(current)
    elif current is not None and len(words) >= 2 and words[1].replace(".", "").isdigit():
        current[words[0]] = float(words[1])
first = frames[0].get(stage, 0.0) + frames[0].get("octree", 0.0)
later = frames[1:]
light = [f.get(stage, 0.0) for f in later]
view = [f.get("view", 0.0) for f in later]
both = [a + b for a, b in zip(light, view)]
print(f"| {method} | {first:.0f} | {statistics.median(light):.0f} | "
      f"{statistics.median(view):.0f} | {statistics.median(both):.0f} |")
PY
done
