#!/usr/bin/env bash
# The smoke solver's benchmarks, in one go: ms per step by stage at 32³, 64³ and 128³ on the set-up
# of Blender's Mantaflow peer (data/scenes/smoke_blender_peer.json, ../shared/peers/README.md §2),
# with the solver's own substeps (CFL 4, as Blender's adaptive default) and with one step per frame
# (the peer's STEPS=fixed1); then speed against error of every advection scheme, ours and OpenVDB's
# tools::VolumeAdvection on the same problems, as a TSV and a PNG.
# Run it on a quiet machine, right after the peer (`../shared/peers/blender_smoke_peer.sh`), and
# compare minima as well as means: the VM is noisy.
# Usage: scripts/bench-smoke.sh [OUT_DIR]       (default out/bench; needs a Release build in build/)
set -euo pipefail
cd "$(dirname "$0")/.."
OUT="${1:-out/bench}"
EIKON=./build/apps/eikon
SCENE=data/scenes/smoke_blender_peer.json
mkdir -p "$OUT"

$EIKON bench smoke "$SCENE" --steps adaptive --tsv "$OUT/smoke_adaptive.tsv" | tee "$OUT/smoke_adaptive.txt"
$EIKON bench smoke "$SCENE" --steps fixed1 --tsv "$OUT/smoke_fixed1.tsv" | tee "$OUT/smoke_fixed1.txt"
$EIKON bench advection --peer openvdb --tsv "$OUT/advection.tsv" | tee "$OUT/advection.txt"
/usr/bin/python3 scripts/plot_advection_bench.py "$OUT/advection.tsv" "$OUT/advection.png"
