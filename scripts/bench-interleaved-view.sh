#!/usr/bin/env bash
# Times the plane sweep's interleaved view against its volume path on the scenes it gained:
# a receiver (data/scenes/glass_sphere_floor.json seen from above, its spot light on the camera's
# side) and dispersion (data/scenes/glass_sphere_fog.json, a directional light from the camera's
# side, its glass given Abbe number 20), with the undispersed fog scene as the baseline.
# Prints one markdown row per run: scene, view, the sweep's and the view's ms (`--stats`; for the
# interleaved view the sweep's share of the frame and the rays'), the samples read behind the
# sweep, the wall time of the whole render and its peak RSS.
# Usage: scripts/bench-interleaved-view.sh [RUNS]
#   The runs are interleaved row by row so that a changing load hits every row alike.
#   EIKON=path/to/eikon picks the binary; BASELINE=path/to/other/eikon adds its interleaved rows
#   of the scenes it can render (labelled "baseline"), to compare two builds in one run.
#   BACKEND=gpu times the GPU path (llvmpipe here: the software driver's cost, not a GPU's).
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${1:-3}
EIKON=${EIKON:-build/apps/eikon}
BASELINE=${BASELINE:-}
BACKEND=${BACKEND:-cpu}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

/usr/bin/python3 - "$OUT" <<'PY'
import copy, json, sys
out = sys.argv[1]
def load(name):
    return json.load(open(f"data/scenes/{name}.json"))
def sweep(scene, view):
    scene = copy.deepcopy(scene)
    scene["render"]["light_transport"] = {"method": "plane_sweep", "plane_sweep": {"view": view}}
    return scene
fog = load("glass_sphere_fog")
fog["lights"] = [{"type": "directional", "direction": [0.3, -0.4, -1.0],
                  "color": [1.0, 0.9, 0.8], "intensity": 3}]
dispersed = copy.deepcopy(fog)
for material in dispersed["materials"]:
    if material.get("ior", 1.0) != 1.0:
        material["abbe"] = 20.0
floor = load("glass_sphere_floor")
floor["camera"] = {"position": [0.3, 4.6, 1.0], "look_at": [0, -0.3, 0], "horizontal_fov_deg": 42}
for name, scene in (("fog", fog), ("fog_abbe20", dispersed), ("floor_from_above", floor)):
    for view in ("volume", "interleaved"):
        json.dump(sweep(scene, view), open(f"{out}/{name}_{view}.json", "w"))
PY

row() {  # binary label scene view
    local log="$OUT/log"
    /usr/bin/time -f "rss %M wall %e" "$1" render "$OUT/$3_$4.json" --backend "$BACKEND" --stats --quiet \
        -o "$OUT/out.png" > "$log" 2>&1
    /usr/bin/python3 - "$log" "$2" "$3" "$4" <<'PY'
import re, sys
log, label, scene, view = sys.argv[1:5]
text = open(log).read()
def stage(name):  # the cpu column: llvmpipe does its GPU work inside the GL calls
    m = re.search(rf"^\s+{name}\s+([0-9.]+)", text, re.M)
    return m.group(1) if m else "-"
behind = re.search(r"([0-9]+) samples behind the sweep", text)
wall = re.search(r"wall ([0-9.]+)", text).group(1)
rss = int(re.search(r"rss ([0-9]+)", text).group(1)) // 1024
print(f"| {scene} | {view} | {label} | {stage('plane_sweep')} | {stage('view')} | "
      f"{behind.group(1) if behind else '-'} | {wall} | {rss} |")
PY
}

echo "| scene | view | binary | sweep ms | view ms | samples behind | render s | peak RSS MB |"
echo "|---|---|---|---:|---:|---:|---:|---:|"
for _ in $(seq "$RUNS"); do
    for scene in fog fog_abbe20 floor_from_above; do
        for view in volume interleaved; do
            row "$EIKON" this "$scene" "$view"
        done
        if [ -n "$BASELINE" ] && [ "$scene" = fog ]; then
            row "$BASELINE" baseline fog interleaved
        fi
    done
done
