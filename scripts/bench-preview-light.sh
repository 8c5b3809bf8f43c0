#!/usr/bin/env bash
# What lighter previews (`eikon view --preview-light lighter`, the default) buy against previews
# traced as set (`--preview-light full`): the time of a frame whose light must be traced again,
# at the preview size. Two scripted cases, the two settings alternating run by run:
#   - a light's gizmo dragged once (glass_sphere_fog.json: the drag's frame, 1/4 size);
#   - a live simulation playing (smoke_glass_mesh.json: the mean of the frames after the first).
# Prints each run's "then X ms a frame" and the medians.
# Usage: scripts/bench-preview-light.sh RUNS [SIZE]   (SIZE default 320x240)
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:-3}"
SIZE="${2:-320x240}"
EIKON=${EIKON:-build/apps/eikon}
LOG=$(mktemp)
echo "# machine: $(nproc) cores; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# command: $0 $*"
frame_ms() {  # the mean frame time after the first, from the viewer's summary
    sed -n 's/^frame time: first frame [0-9.]* ms, then \([0-9.]*\) ms a frame.*/\1/p'
}
for run in $(seq 1 "$RUNS"); do
    for light in lighter full; do
        drag=$(xvfb-run -a "$EIKON" view data/scenes/glass_sphere_fog.json --backend cpu \
                   --size "$SIZE" --exit-after 2 --drag lights/0:0,-6 --preview-light "$light" \
                   | frame_ms)
        play=$(xvfb-run -a "$EIKON" view data/scenes/smoke_glass_mesh.json --backend cpu \
                   --size "$SIZE" --play --exit-after 24 --preview-light "$light" | frame_ms)
        echo "$light light-drag $drag playing $play" | tee -a "$LOG"
    done
done
/usr/bin/python3 - "$LOG" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    light, _, drag, _, play = line.split()
    runs.setdefault(light, ([], []))
    runs[light][0].append(float(drag))
    runs[light][1].append(float(play))
for light, (drag, play) in runs.items():
    print(f"median of {len(drag)}, --preview-light {light}: light drag {statistics.median(drag):.1f} "
          f"ms a frame, playing {statistics.median(play):.1f} ms a frame")
PY
rm -f "$LOG"
