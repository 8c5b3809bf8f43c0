#!/usr/bin/env bash
# What `import eikon` costs against the command line (issue 19): the same frame of
# glass_sphere_fog.json at 320x240 on the CPU twin, rendered by `eikon render` (a process: start,
# read the scene, render, write the PNG) and by the Python module (open the scene, render to
# numpy), and re-rendered in the same Python session after a camera change (the session keeps its
# fields and illumination). Medians of --reps runs.
# Usage: scripts/bench-python.sh [--reps N] [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
REPS=3
if [ "${1:-}" = "--reps" ]; then REPS=$2; shift 2; fi
BUILD=${1:-build}
SCENE=data/scenes/glass_sphere_fog.json
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
PYTHONPATH="$BUILD/python" /usr/bin/python3 - "$BUILD/apps/eikon" "$SCENE" "$REPS" "$TMP" <<'PY'
import statistics, subprocess, sys, time
import eikon
binary, scene, reps, tmp = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]

def median_seconds(run):
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return statistics.median(times)

cli = median_seconds(lambda: subprocess.run(
    [binary, "render", scene, "-o", f"{tmp}/cli.png", "--size", "320x240", "--backend", "cpu",
     "--quiet"], check=True))

def python_frame():
    session = eikon.Session.open(scene, eikon.Device.CPU)
    session.set_image_size(320, 240)
    session.render(0).rgb.sum()

python = median_seconds(python_frame)
session = eikon.Session.open(scene, eikon.Device.CPU)
session.set_image_size(320, 240)
session.render(0)

def camera_moved():
    camera = session.camera
    camera.horizontal_fov_degrees += 0.5
    session.camera = camera
    session.render(0)

again = median_seconds(camera_moved)
print("| run (glass_sphere_fog.json, 320x240, CPU twin) | seconds | against eikon render |")
print("|---|---|---|")
print(f"| eikon render (a process, PNG written) | {cli:.3f} | 1.00 |")
print(f"| Python: Session.open + render to numpy | {python:.3f} | {python / cli:.2f} |")
print(f"| Python: render again after a camera change | {again:.3f} | {again / cli:.2f} |")
PY
