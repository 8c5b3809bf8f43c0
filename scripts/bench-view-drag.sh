#!/usr/bin/env bash
# Times what one mouse drag of an ARAP handle costs in `eikon view`: the ARAP solve of the drag
# (sim/arap_drag.h dragCurrentFrame) and the stages of the frame it shows (voxelize, photons,
# view, ...), from the view's scripted drag (--drag, the same code path as the right mouse
# button). Runs the viewer RUNS times per backend under xvfb-run and prints each run's line and
# the median of every stage.
# Usage: scripts/bench-view-drag.sh RUNS SCENE HANDLE:DX,DY BACKENDS
#   e.g. scripts/bench-view-drag.sh 5 data/scenes/glass_squeezed.json glass/top:0,-25 "cpu gpu"
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="$1"; SCENE="$2"; DRAG="$3"; BACKENDS="$4"
EIKON=${EIKON:-build/apps/eikon}
LOG=$(mktemp)
echo "# machine: $(nproc) cores; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# command: $0 $*"
for run in $(seq 1 "$RUNS"); do
    for backend in $BACKENDS; do
        line=$(xvfb-run -a "$EIKON" view "$SCENE" --exit-after 2 --backend "$backend" \
                   --drag "$DRAG" | grep "^the drag's frame: ")
        echo "$backend $line" | tee -a "$LOG"
    done
done
/usr/bin/python3 - "$LOG" <<'PY'
import re, statistics, sys
runs = {}
for line in open(sys.argv[1]):
    backend, rest = line.split(" ", 1)
    stages = re.findall(r"([A-Za-z][A-Za-z ]*?) ([0-9.]+) ms", rest.split(": ", 1)[1])
    for name, ms in stages:
        runs.setdefault(backend, {}).setdefault(name.strip(), []).append(float(ms))
for backend, stages in runs.items():
    total = [sum(v) for v in zip(*stages.values())]
    cells = "  ".join(f"{n} {statistics.median(v):.1f}" for n, v in stages.items())
    print(f"median of {len(total)}, {backend}: {cells}  | sum {statistics.median(total):.1f} ms")
PY
rm -f "$LOG"
