#!/usr/bin/env bash
# Times the relighting pipeline's stages on the glass-sphere scene (data/scenes/glass_sphere_fog.json,
# a spot light through a glass ball in fog) at the sizes issue 3 names: 64³ volume / 128² photons /
# 320x240 and 128³ / 512² / 640x480, on both backends (on this machine the GPU is llvmpipe).
# RUNS runs each; prints eikon's per-stage table and photon counts of every run, so min and median
# can be read off.  Usage: scripts/bench-photons.sh [RUNS] [BACKENDS]  (default 3, "cpu gpu")
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:-3}"
BACKENDS="${2:-cpu gpu}"
EIKON=build/apps/eikon
OUT=$(mktemp -d)
[ -x "$EIKON" ] || bash scripts/build.sh

# A copy of the scene with another resolution, photon count and image size (no file paths in it).
variant() {  # resolution per_side width height -> path
    local path="$OUT/glass_${1}_${2}_${3}.json"
    /usr/bin/python3 - "$1" "$2" "$3" "$4" "$path" <<'PY'
import json, sys
res, side, w, h, path = sys.argv[1:]
scene = json.load(open("data/scenes/glass_sphere_fog.json"))
scene["volume"]["resolution"] = int(res)
scene["render"].update({"width": int(w), "height": int(h)})
scene["render"]["light_transport"] = {"photons": {"per_side": int(side)}}
scene["output"] = {"directory": sys.argv[5] + ".out", "name": "frame"}
json.dump(scene, open(path, "w"))
PY
    echo "$path"
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for size in "64 128 320 240" "128 512 640 480"; do
    scene=$(variant $size)
    for backend in $BACKENDS; do
        for run in $(seq 1 "$RUNS"); do
            echo "== volume ${size%% *}^3, photons/side, image: $size | backend $backend | run $run"
            "$EIKON" render "$scene" --backend "$backend" --stats | grep -v '^wrote'
        done
    done
done
