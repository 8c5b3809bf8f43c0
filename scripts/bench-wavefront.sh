#!/usr/bin/env bash
# Times the wavefront method (docs/methods.md `wavefront`) on the GPU against its CPU twin, on the
# scenes of its comparison with photons: data/scenes/glass_sphere_fog.json (64³) and
# three_glass_cube.json (64³), each with render.light_transport.method set to "wavefront".
# Prints one markdown row per run: scene, backend, the wavefront stage's ms (`--stats`), its
# patches, splits, steps and rounds, the wall time of the whole render and its peak RSS; then,
# per scene, `eikon diff` of the last GPU picture against the last CPU one.
# Usage: scripts/bench-wavefront.sh [RUNS]
#   The runs alternate backends row by row so that a changing load hits both alike.
#   EIKON=path/to/eikon picks the binary. On this machine the GPU is llvmpipe: its figures are
#   the software driver's cost on the CPU, not a GPU's.
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${1:-3}
EIKON=${EIKON:-build/apps/eikon}
SCENES=${SCENES:-glass_sphere_fog three_glass_cube}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

for scene in $SCENES; do
    /usr/bin/python3 - "$scene" "$OUT" <<'PY'
import json, os, sys
name, out = sys.argv[1:3]
folder = os.path.abspath("data/scenes")
scene = json.load(open(f"{folder}/{name}.json"))
scene.setdefault("render", {})["light_transport"] = {"method": "wavefront"}
def absolute(node):  # the scene's files (meshes, VDBs, environments) from its own folder
    if isinstance(node, dict):
        for key, value in node.items():
            if key in ("file", "path") and isinstance(value, str) and not os.path.isabs(value):
                node[key] = os.path.normpath(os.path.join(folder, value))
            else:
                absolute(value)
    elif isinstance(node, list):
        for value in node:
            absolute(value)
absolute(scene)
os.makedirs(f"{out}/scenes", exist_ok=True)
json.dump(scene, open(f"{out}/scenes/{name}.wavefront.json", "w"))
PY
done

row() {  # scene backend
    local log="$OUT/log"
    (cd "$OUT/scenes" && /usr/bin/time -f "rss %M wall %e" "$OLDPWD/$EIKON" render \
        "$1.wavefront.json" --backend "$2" --stats --quiet -o "$OUT/$1_$2.exr") > "$log" 2>&1
    /usr/bin/python3 - "$log" "$1" "$2" <<'PY'
import re, sys
log, scene, backend = sys.argv[1:4]
text = open(log).read()
def stage(name):
    m = re.search(rf"^\s+{name}\s+([0-9.]+)", text, re.M)
    return m.group(1) if m else "-"
def count(pattern):
    m = re.search(pattern, text)
    return m.group(1) if m else "-"
wall = re.search(r"wall ([0-9.]+)", text).group(1)
rss = int(re.search(r"rss ([0-9]+)", text).group(1)) // 1024
print(f"| {scene} | {backend} | {stage('wavefront')} | {count(r'wavefront: ([0-9]+) traced')} | "
      f"{count(r'wavefront: ([0-9]+) split')} | {count(r'traced, ([0-9]+) steps')} | "
      f"{count(r'([0-9]+) rounds')} | {wall} | {rss} |")
PY
}

echo "| scene | backend | wavefront ms | patches | splits | steps | rounds | render s | peak RSS MB |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
for _ in $(seq "$RUNS"); do
    for scene in $SCENES; do
        for backend in cpu gpu; do row "$scene" "$backend"; done
    done
done
for scene in $SCENES; do
    echo "$scene: eikon diff gpu cpu"
    "$EIKON" diff "$OUT/${scene}_gpu.exr" "$OUT/${scene}_cpu.exr" || true
done
