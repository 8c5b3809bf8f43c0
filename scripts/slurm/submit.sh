#!/usr/bin/env bash
# Renders a scene's frames on a Slurm cluster: one job runs `eikon simulate` when the scene has a
# "simulation" section (its frames depend on each other, so one task steps them all, in order),
# then a job array renders the frames in CHUNKS chunks, each task its own contiguous piece
# (`eikon render --chunk auto`), from the simulation's cache (`--from-cache`), held until the
# simulation succeeded (--dependency=afterok); a last job merges the tasks' manifests into one
# that equals, byte for byte, the manifest of the same render on one machine
# (scripts/slurm/README.md). Tasks rerun with --resume: a requeued or resubmitted task renders
# only the frames that are missing or not this render's.
#
# Usage: scripts/slurm/submit.sh SCENE FRAMES CHUNKS [sbatch options...]
#   SCENE    a scene file (JSON) on the shared filesystem
#   FRAMES   eikon's --frames grammar: 1-240, 1-240x2, 1,5,9-12
#   CHUNKS   how many array tasks share the frames
#   sbatch options go to every job (--partition, --account, --time, --mem, ...)
# Environment:
#   EIKON      the eikon binary every node runs (default: build/apps/eikon of this checkout)
#   OUT        where frames, manifests and logs go (default: out/farm/<scene name>)
#   EIKON_RENDER_ARGS   more `eikon render` options for every task (e.g. "--backend cpu --exr")
set -euo pipefail

if [ $# -lt 3 ]; then
    sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//' >&2
    exit 2
fi
SCENE=$1 FRAMES=$2 CHUNKS=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
EIKON=${EIKON:-$here/../../build/apps/eikon}
fail() { echo "eikon: scripts/slurm/submit.sh: $*" >&2; exit 1; }
[ -f "$SCENE" ] || fail "$SCENE: no such scene file"
[ -x "$EIKON" ] || fail "$EIKON: not an executable eikon (build it, or set EIKON)"
[[ "$CHUNKS" =~ ^[1-9][0-9]{0,5}$ ]] || fail "CHUNKS: expected a whole number from 1, got '$CHUNKS'"
[[ "$FRAMES" =~ ^[0-9]+(-[0-9]+(x[0-9]+)?)?(,[0-9]+(-[0-9]+(x[0-9]+)?)?)*$ ]] ||
    fail "FRAMES: expected 7, 1-10, 1-10x2 or a comma list of those, got '$FRAMES'"
command -v sbatch >/dev/null || fail "sbatch not found: run this on a Slurm login node"

SCENE=$(cd "$(dirname "$SCENE")" && pwd)/$(basename "$SCENE")
EIKON=$(cd "$(dirname "$EIKON")" && pwd)/$(basename "$EIKON")
name=$(basename "$SCENE" .json)
OUT=${OUT:-out/farm/$name}
mkdir -p "$OUT/logs" "$OUT/manifests"
OUT=$(cd "$OUT" && pwd)

# The first and last frame asked for: the simulation writes that run.
first="" last=""
IFS=, read -ra pieces <<<"$FRAMES"
for piece in "${pieces[@]}"; do
    a=${piece%%-*} b=${piece#*-}
    b=${b%%x*}
    [ "$piece" = "$a" ] && b=$a
    a=$((10#$a)) b=$((10#$b))
    { [ -z "$first" ] || [ "$a" -lt "$first" ]; } && first=$a
    { [ -z "$last" ] || [ "$b" -gt "$last" ]; } && last=$b
done

# A "simulation" section (a key whose value is an object), newlines aside.
simulated=0
tr -d '\n' <"$SCENE" | grep -Eq '"simulation"[[:space:]]*:[[:space:]]*\{' && simulated=1

dependency=()
from_cache=""
if [ "$simulated" = 1 ]; then
    sim_job=$(sbatch --parsable "$@" --job-name "eikon-simulate-$name" \
        --output "$OUT/logs/simulate_%j.txt" \
        --wrap "exec '$EIKON' simulate '$SCENE' --frames $first-$last")
    sim_job=${sim_job%%;*}
    dependency=(--dependency "afterok:$sim_job")
    from_cache="--from-cache"
    echo "simulation: job $sim_job (eikon simulate, frames $first-$last), log $OUT/logs/simulate_$sim_job.txt"
fi

render_job=$(sbatch --parsable "$@" "${dependency[@]}" --job-name "eikon-render-$name" \
    --array "0-$((CHUNKS - 1))" --output "$OUT/logs/render_%A_%a.txt" \
    --wrap "exec '$EIKON' render '$SCENE' --frames '$FRAMES' --chunk auto $from_cache \
-o '$OUT/' --manifest '$OUT/manifests/chunk_'\$SLURM_ARRAY_TASK_ID'.tsv' --resume ${EIKON_RENDER_ARGS:-}")
render_job=${render_job%%;*}
echo "render: job array $render_job ($CHUNKS tasks, frames $FRAMES), logs $OUT/logs/render_${render_job}_*.txt"

merge_job=$(sbatch --parsable "$@" --dependency "afterok:$render_job" \
    --job-name "eikon-manifest-$name" --output "$OUT/logs/manifest_%j.txt" \
    --wrap "exec bash '$here/merge-manifests.sh' '$OUT/manifest.tsv' '$OUT'/manifests/chunk_*.tsv")
merge_job=${merge_job%%;*}
echo "manifest: job $merge_job -> $OUT/manifest.tsv"
echo "frames: $OUT/ (check: cmp $OUT/manifest.tsv <a local run's --manifest)"
