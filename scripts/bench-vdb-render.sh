#!/usr/bin/env bash
# Times `eikon render` on the Houdini smoke cache at 640x480 against OpenVDB's vdb_render (the
# peer in ../shared/peers/vdb_render_peer.sh, same camera, light, steps and coefficients), one
# after the other in this session. Prints min and median wall time of whole processes over RUNS
# runs, and eikon's per-stage times of its last run.  Usage: scripts/bench-vdb-render.sh [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:-5}"
VDB=../shared/data/vdb/houdini_smoke1.vdb
SCENE=data/scenes/houdini_smoke.json
OUT=$(mktemp -d)
command -v vdb_render >/dev/null || bash scripts/install-deps.sh

stats() {  # min and median of the arguments
    printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {printf "%.2f %.2f\n", a[1], a[int((NR+1)/2)]}'
}

time_runs() {  # label, command...
    local label=$1; shift
    local times=()
    for _ in $(seq 1 "$RUNS"); do
        local t0 t1
        t0=$(date +%s.%N); "$@" > "$OUT/last.log" 2>&1; t1=$(date +%s.%N)
        times+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN{print b-a}')")
    done
    read -r tmin tmed < <(stats "${times[@]}")
    printf '%-44s min %6.2f s   median %6.2f s\n' "$label" "$tmin" "$tmed"
    grep -E '^ +(load|resample|upload|light|view|readback|write) ' "$OUT/last.log" | sed 's/^/      /' || true
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "GL: $(./build/apps/eikon render "$SCENE" -o "$OUT" --size 8x6 --backend gpu | head -1)"
time_runs "vdb_render (peer, -step 1 -shadowstep 3)" \
    vdb_render "$VDB" "$OUT/peer.png" -res 640x480 -cpus 0 -step 1 -shadowstep 3 -gain 0.2 \
    -cutoff 0.005 -light 1,1,0.5,1,1,1 -translate -7.4,40.4,200 -scatter 0.3,0.3,0.3 \
    -absorb 0.05,0.05,0.05
for mode in volume swept marched; do
    time_runs "eikon GPU (llvmpipe), shadows $mode" \
        ./build/apps/eikon render "$SCENE" -o "$OUT" --stats --backend gpu --shadows "$mode"
    time_runs "eikon CPU twin, shadows $mode" \
        ./build/apps/eikon render "$SCENE" -o "$OUT" --stats --backend cpu --shadows "$mode"
done
rm -rf "$OUT"
