#!/usr/bin/env bash
# What a directional light's disc costs a light-transport method
# (docs/methods.md#soft-distant-lights): data/scenes/soft_sun_slats.json rendered by METHOD with
# each angular diameter, RUNS separate processes each (a process renders its frame once: nothing
# is cached between runs), CPU twin. Prints one markdown row per diameter: the median of the
# method's stage and of the view pass, in ms.
# Usage: [METHOD=plane_sweep|light_volumes] scripts/bench-soft-light.sh [RUNS] [DIAMETERS]
#        e.g. METHOD=light_volumes scripts/bench-soft-light.sh 5 "0 0.53 8 20"
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${1:-5}
DIAMETERS=${2:-"0 0.53 8 20"}
EIKON=${EIKON:-build/apps/eikon}
METHOD=${METHOD:-plane_sweep}
case "$METHOD" in  # the method's row in `eikon render --stats`
    light_volumes) STAGE=light ;;
    *) STAGE=$METHOD ;;
esac
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

echo "| angular diameter | $METHOD ms (median of $RUNS) | view ms |"
echo "|---:|---:|---:|"
for diameter in $DIAMETERS; do
    /usr/bin/python3 - "$diameter" "$METHOD" "$OUT/scene.json" <<'PY'
import json, sys
diameter, method, path = sys.argv[1:4]
scene = json.load(open("data/scenes/soft_sun_slats.json"))
scene["lights"][0]["angular_diameter_deg"] = float(diameter)
scene["render"]["light_transport"]["method"] = method
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
    /usr/bin/python3 - "$OUT/stats.txt" "$diameter" "$STAGE" <<'PY'
import statistics, sys
path, diameter, method = sys.argv[1:4]
stages = {method: [], "view": []}
for line in open(path):
    words = line.split()
    if len(words) >= 2 and words[0] in stages:
        stages[words[0]].append(float(words[1]))
if not stages[method]:
    sys.exit(f"eikon: bench-soft-light: no '{method}' stage in eikon render --stats")
print(f"| {diameter}° | {statistics.median(stages[method]):.1f} | "
      f"{statistics.median(stages['view']):.1f} |")
PY
done
