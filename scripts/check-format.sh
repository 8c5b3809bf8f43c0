#!/usr/bin/env bash
# Fails when a C++ file differs from what clang-format makes of it under the repository's
# .clang-format. Debian 12's clang-format (14, from scripts/install-deps.sh) is the reference:
# other versions format some constructs differently. CLANG_FORMAT=path picks another binary.
#
# Usage: scripts/check-format.sh [ROOT]   (ROOT defaults to this repository)
set -euo pipefail
ROOT="${1:-$(dirname "$0")/..}"
cd "$ROOT"
CLANG_FORMAT="${CLANG_FORMAT:-clang-format}"
FOLDERS=(core sim render apps tests shaders/shared)

if ! command -v "$CLANG_FORMAT" >/dev/null; then
    echo "eikon: $CLANG_FORMAT not found (bash scripts/install-deps.sh installs it)" >&2
    exit 1
fi
# Without it clang-format would look further up, or fall back to LLVM style, and judge wrongly.
[ -f .clang-format ] || { echo "eikon: no .clang-format in $(pwd)" >&2; exit 1; }

# Tracked files when ROOT is a checkout of its own (build trees and scratch files stay out);
# every file otherwise, e.g. a copy made by tests/scripts/test_checks.sh.
if [ "$(git rev-parse --show-toplevel 2>/dev/null)" = "$(pwd -P)" ]; then
    mapfile -t files < <(git ls-files -- "${FOLDERS[@]/%//*.h}" "${FOLDERS[@]/%//*.cpp}")
else
    mapfile -t files < <(find "${FOLDERS[@]}" -type f \( -name '*.h' -o -name '*.cpp' \) | sort)
fi

# clang-format with no file names would read stdin and wait.
((${#files[@]})) || { echo "eikon: no C++ files in ${FOLDERS[*]} under $(pwd)" >&2; exit 1; }

# One clang-format run for all files (a process per file takes 30 s here); each file it would
# change gets one "FILE:LINE:COL: error: code should be clang-formatted" line.
status=0
output="$("$CLANG_FORMAT" --dry-run -Werror --ferror-limit=1 "${files[@]}" 2>&1)" || status=$?
mapfile -t unformatted < <(
    sed -nE 's/^(.+):[0-9]+:[0-9]+: error: code should be clang-formatted.*/\1/p' <<<"$output" |
        sort -u
)
if ((status != 0 && ${#unformatted[@]} == 0)); then
    echo "$output" >&2 # clang-format itself failed (bad .clang-format, unreadable file)
    exit 1
fi
for file in "${unformatted[@]}"; do
    echo "eikon: $file: not formatted (clang-format -i $file)" >&2
done
((${#unformatted[@]} == 0)) || exit 1
echo "format: ${#files[@]} files, all as clang-format makes them"
