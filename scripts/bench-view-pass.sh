#!/usr/bin/env bash
# The CPU twin's viewing pass (and the photon march beside it) at issue 18's sizes, builds
# against each other in one session, alternating run by run: glass_sphere_fog.json at 128³ /
# 512² photons / 640×480, and houdini_smoke.json at 640×480 with OpenVDB's vdb_render timed in
# the same runs (the peer's command of scripts/bench-vdb-render.sh). Each BUILD is a path to an
# `eikon` binary, optionally followed by ",VAR=value" settings for its runs (for example
# "build/apps/eikon,EIKON_SKIP_EMPTY_SPACE=0"). Prints every run's stage times and the medians.
# Usage: scripts/bench-view-pass.sh RUNS BUILD [BUILD...]
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:?usage: $0 RUNS BUILD [BUILD...]}"
shift
[ $# -ge 1 ] || { echo "usage: $0 RUNS BUILD [BUILD...]" >&2; exit 2; }
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
VDB=../shared/data/vdb/houdini_smoke1.vdb
/usr/bin/python3 - "$OUT/glass_128.json" <<'PY'
import json, os, sys
scene = json.load(open("data/scenes/glass_sphere_fog.json"))
scene["volume"]["resolution"] = 128
scene["render"].update({"width": 640, "height": 480})
scene["render"]["light_transport"] = {"photons": {"per_side": 512}}
scene["output"] = {"directory": os.path.dirname(sys.argv[1]), "name": "frame"}
json.dump(scene, open(sys.argv[1], "w"))
PY
echo "# machine: $(nproc) cores; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# command: $0 $RUNS $*"
stage() {  # stage name, log -> ms
    sed -n "s/^ *$1 \+\([0-9.]\+\) .*/\1/p" "$2" | head -1
}
LOG="$OUT/runs.tsv"
for run in $(seq 1 "$RUNS"); do
    t0=$(date +%s.%N)
    vdb_render "$VDB" "$OUT/peer.png" -res 640x480 -cpus 0 -step 1 -shadowstep 3 -gain 0.2 \
        -cutoff 0.005 -light 1,1,0.5,1,1,1 -translate -7.4,40.4,200 -scatter 0.3,0.3,0.3 \
        -absorb 0.05,0.05,0.05 > /dev/null 2>&1
    t1=$(date +%s.%N)
    printf 'vdb_render\t%s\tpeer\t%.0f\n' "$run" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{print (b-a)*1000}')" |
        tee -a "$LOG"
    for build in "$@"; do
        IFS=, read -r -a parts <<< "$build"
        settings=("${parts[@]:1}")
        env "${settings[@]}" "${parts[0]}" render "$OUT/glass_128.json" --backend cpu --stats \
            --quiet -o "$OUT/glass.png" > "$OUT/glass.log" 2>&1
        t0=$(date +%s.%N)
        env "${settings[@]}" "${parts[0]}" render data/scenes/houdini_smoke.json --backend cpu \
            --stats --quiet -o "$OUT/smoke.png" > "$OUT/smoke.log" 2>&1
        t1=$(date +%s.%N)
        printf '%s\t%s\tglass view\t%s\n' "$build" "$run" "$(stage view "$OUT/glass.log")" | tee -a "$LOG"
        printf '%s\t%s\tglass photons\t%s\n' "$build" "$run" "$(stage photons "$OUT/glass.log")" | tee -a "$LOG"
        printf '%s\t%s\tsmoke view\t%s\n' "$build" "$run" "$(stage view "$OUT/smoke.log")" | tee -a "$LOG"
        printf '%s\t%s\tsmoke wall\t%.0f\n' "$build" "$run" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{print (b-a)*1000}')" | tee -a "$LOG"
        cp "$OUT/glass.png" "$OUT/glass-$(echo "$build" | md5sum | cut -c1-8).png"
        cp "$OUT/smoke.png" "$OUT/smoke-$(echo "$build" | md5sum | cut -c1-8).png"
    done
done
echo "# pictures, glass_sphere_fog then houdini_smoke, one md5 per build (equal: the same bytes):"
for build in "$@"; do
    tag=$(echo "$build" | md5sum | cut -c1-8)
    echo "$build $(md5sum < "$OUT/glass-$tag.png" | cut -c1-12) $(md5sum < "$OUT/smoke-$tag.png" | cut -c1-12)"
done
/usr/bin/python3 - "$LOG" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    build, _, what, ms = line.rstrip("\n").split("\t")
    runs.setdefault((build, what), []).append(float(ms))
print("# medians, ms")
for (build, what), values in runs.items():
    print(f"{build:60s} {what:14s} {statistics.median(values):9.1f}  ({', '.join(f'{v:.0f}' for v in values)})")
PY
