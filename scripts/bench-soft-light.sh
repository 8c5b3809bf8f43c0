#!/usr/bin/env bash
# What a directional light's disc costs the plane sweep (docs/methods.md#soft-distant-lights):
# data/scenes/soft_sun_slats.json rendered with each angular diameter, RUNS separate processes
# each (a process renders its frame once: nothing is cached between runs), CPU twin. Prints one
# markdown row per diameter: the median plane_sweep stage and view pass, in ms.
# Usage: scripts/bench-soft-light.sh [RUNS] [DIAMETERS]   e.g. 5 "0 0.53 8 20"
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${1:-5}
DIAMETERS=${2:-"0 0.53 8 20"}
EIKON=${EIKON:-build/apps/eikon}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

echo "| angular diameter | plane_sweep ms (median of $RUNS) | view ms |"
echo "|---:|---:|---:|"
for diameter in $DIAMETERS; do
    /usr/bin/python3 - "$diameter" "$OUT/scene.json" <<'PY'
import json, sys
diameter, path = sys.argv[1:3]
scene = json.load(open("data/scenes/soft_sun_slats.json"))
scene["lights"][0]["angular_diameter_deg"] = float(diameter)
json.dump(scene, open(path, "w"))
PY
    : >"$OUT/stats.txt"
    for _ in $(seq "$RUNS"); do
        "$EIKON" render "$OUT/scene.json" --backend cpu --stats --quiet -o "$OUT/frame.png" \
            >>"$OUT/stats.txt" 2>&1 || {
            echo "eikon: bench-soft-light: diameter $diameter failed:" >&2
            cat "$OUT/stats.txt" >&2
            exit 1
        }
    done
    /usr/bin/python3 - "$OUT/stats.txt" "$diameter" <<'PY'
import statistics, sys
path, diameter = sys.argv[1:3]
stages = {"plane_sweep": [], "view": []}
for line in open(path):
    words = line.split()
    if len(words) >= 2 and words[0] in stages:
        stages[words[0]].append(float(words[1]))
print(f"| {diameter}° | {statistics.median(stages['plane_sweep']):.1f} | "
      f"{statistics.median(stages['view']):.1f} |")
PY
done
