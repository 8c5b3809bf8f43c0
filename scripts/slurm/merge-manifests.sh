#!/usr/bin/env bash
# Merges the manifests of a render's chunks (`eikon render --chunk K/N --manifest FILE`) into one:
# the header they share, then every frame line sorted by frame. The result equals the manifest of
# the same render in one process, byte for byte, when every frame was rendered alike.
# Usage: scripts/slurm/merge-manifests.sh OUTPUT CHUNK_MANIFEST...
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 OUTPUT CHUNK_MANIFEST..." >&2; exit 2; }
out=$1
shift
first=$1
header=$(head -n 6 "$first")
for m in "$@"; do
    [ "$(head -n 6 "$m")" = "$header" ] ||
        { echo "eikon: $m: another render than $first (its header differs)" >&2; exit 1; }
done
{
    printf '%s\n' "$header"
    for m in "$@"; do tail -n +7 "$m"; done | LC_ALL=C sort -s -t "$(printf '\t')" -k1,1n
} >"$out.partial"
mv "$out.partial" "$out"
echo "merged $# manifests: $(($(wc -l <"$out") - 6)) files -> $out"
