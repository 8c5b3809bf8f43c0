#!/usr/bin/env bash
# Times the photon stage of the glass-sphere scene (data/scenes/glass_sphere_fog.json, as in
# scripts/bench-photons.sh) for several march settings (render.light_transport.photons.steps_per_round and
# stop_fraction), runs interleaved so that a changing load hits every setting alike. Prints one
# line per run: size, backend, setting, photon-stage ms (the larger of its CPU and GPU columns),
# photon steps, photons cut, rounds.
# Usage: scripts/bench-photon-rounds.sh RUNS "RES SIDE" BACKENDS SETTING...
#   SETTING: "K:F" (steps_per_round K, stop_fraction F) or "before" (the binary $BEFORE with
#   its shaders in $BEFORE_SHADERS: a build without these settings). The image is 64x48
#   (--size): the photon stage does not depend on it, the view pass would only add time.
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="$1"; SIZE="$2"; BACKENDS="$3"; shift 3
EIKON=${EIKON:-build/apps/eikon}
OUT=$(mktemp -d)
read -r RES SIDE <<<"$SIZE"

variant() {  # per_side [K F] -> path
    local path="$OUT/glass_${RES}_$1_${2:-x}_${3:-x}.json"
    /usr/bin/python3 - "$RES" "$path" "$@" <<'PY'
import json, sys
res, path, side = sys.argv[1], sys.argv[2], int(sys.argv[3])
scene = json.load(open("data/scenes/glass_sphere_fog.json"))
scene["volume"]["resolution"] = int(res)
photons = {"per_side": side}
if len(sys.argv) > 4:
    photons.update({"steps_per_round": int(sys.argv[4]), "stop_fraction": float(sys.argv[5])})
scene["render"]["light_transport"] = {"photons": photons}
scene["output"] = {"directory": path + ".out", "name": "frame"}
json.dump(scene, open(path, "w"))
PY
    echo "$path"
}

echo "# machine: $(nproc) cores; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for run in $(seq 1 "$RUNS"); do
    for backend in $BACKENDS; do
        for setting in "$@"; do
            if [ "$setting" = before ]; then
                scene=$(variant "$SIDE")
                out=$(EIKON_SHADER_DIR="$BEFORE_SHADERS" "$BEFORE" render "$scene" --backend "$backend" --stats --size 64x48)
            else
                scene=$(variant "$SIDE" "${setting%%:*}" "${setting##*:}")
                out=$("$EIKON" render "$scene" --backend "$backend" --stats --size 64x48)
            fi
            echo "$out" | /usr/bin/python3 -c '
import re, sys
text = sys.stdin.read()
cols = re.search(r"^\s+photons\s+([\d.]+)\s+([\d.]+|-)", text, re.M).groups()
ms = max(float(x) for x in cols if x != "-")
steps = re.search(r"photons: \d+ traced, (\d+) steps", text).group(1)
m = re.search(r"(\d+) cut, (\d+) rounds", text)
cut, rounds = m.groups() if m else ("-", "-")
print(f"{sys.argv[1]}^3/{sys.argv[2]}^2 {sys.argv[3]} {sys.argv[4]} run {sys.argv[5]}: photons {ms} ms, {steps} steps, {cut} cut, {rounds} rounds")
' "$RES" "$SIDE" "$backend" "$setting" "$run"
        done
    done
done
