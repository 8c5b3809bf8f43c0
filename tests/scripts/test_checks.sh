#!/usr/bin/env bash
# scripts/check-layering.sh and scripts/check-format.sh pass on a copy of the tree and fail, naming
# the file, on a violation planted in that copy (the repository itself is never touched). Each
# case expects one line of output and the exit status the check should give.
set -euo pipefail
REPO="$(cd "$(dirname "$0")/../.." && pwd)"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
TREE="$WORK/tree"
mkdir "$TREE" "$WORK/saved"
# The folders the checks read; no build trees.
cp -r "$REPO"/{core,sim,render,pipeline,api,include,python,apps,shaders,tests,CMakeLists.txt,.clang-format} \
    "$TREE"/

passed=0 failed=0

# expect NAME CHECK STATUS REGEX: scripts/check-CHECK.sh on the copy must exit with STATUS and
# print exactly one line, matching REGEX (grep -E, whole line).
expect() {
    local name="$1" check="$2" status="$3" regex="$4" output line rc=0
    output="$(bash "$REPO/scripts/check-$check.sh" "$TREE" 2>&1)" || rc=$?
    if [ "$rc" = "$status" ] && [ "$(wc -l <<<"$output")" = 1 ] && grep -qxE "$regex" <<<"$output"
    then
        echo "pass: $name"
        passed=$((passed + 1))
    else
        echo "FAIL: $name (exit $rc, expected $status and one line matching: $regex)"
        while IFS= read -r line; do echo "    $line"; done <<<"$output"
        failed=$((failed + 1))
    fi
}

# plant FILE TEXT puts TEXT as line 2 of the copy's FILE; restore puts every planted file back.
plant() {
    [ -f "$WORK/saved/${1//\//_}" ] || cp "$TREE/$1" "$WORK/saved/${1//\//_}"
    sed -i "1a $2" "$TREE/$1"
    planted+=("$1")
}
restore() {
    for f in "${planted[@]}"; do cp "$WORK/saved/${f//\//_}" "$TREE/$f"; done
    planted=()
}
planted=()

# The first source of a library in the copy, so that renames elsewhere do not break the test.
first_cpp() { (cd "$TREE" && find "$1" -maxdepth 1 -name '*.cpp' | sort | head -n 1); }
core_cpp="$(first_cpp core)" sim_cpp="$(first_cpp sim)" render_cpp="$(first_cpp render)"
apps_cpp="$(first_cpp apps)" pipeline_cpp="$(first_cpp pipeline)"

# ---- layering -------------------------------------------------------------------------------
expect "layering passes on the tree" layering 0 \
    'layering: [0-9]+ files, no include crosses the library direction'

plant "$core_cpp" '#include "render/gl_context.h"'
expect "core including render fails" layering 1 \
    "eikon: $core_cpp:2: core must not include render/gl_context.h \(core may include: .*\)"
restore

plant "$sim_cpp" '#include "render/image.h"'
expect "sim including render fails" layering 1 \
    "eikon: $sim_cpp:2: sim must not include render/image.h \(sim may include: .*\)"
restore

plant "$render_cpp" '#include "sim/clock.h"'
expect "render including sim fails" layering 1 \
    "eikon: $render_cpp:2: render must not include sim/clock.h \(render may include: .*\)"
restore

plant "$core_cpp" '#include <epoxy/gl.h>'
expect "core including a GL header fails" layering 1 \
    "eikon: $core_cpp:2: core must not include <epoxy/gl.h> .*"
restore

plant sim/CMakeLists.txt 'target_link_libraries(eikon_sim PRIVATE eikon_render)'
expect "sim linking eikon_render fails" layering 1 \
    "eikon: sim/CMakeLists.txt:2: sim must not link eikon_render .*"
restore

# apps makes no GL call of its own: GL headers fail there, GLFW (the viewer's events) passes.
plant "$apps_cpp" '#include <epoxy/gl.h>'
expect "apps including a GL header fails" layering 1 \
    "eikon: $apps_cpp:2: apps must not include <epoxy/gl.h> .*"
restore

plant "$apps_cpp" '#include <GLFW/glfw3.h>'
expect "apps including GLFW passes" layering 0 \
    'layering: [0-9]+ files, no include crosses the library direction'
restore

plant apps/CMakeLists.txt 'target_link_libraries(eikon PRIVATE PkgConfig::EPOXY)'
expect "apps linking epoxy fails" layering 1 \
    "eikon: apps/CMakeLists.txt:2: apps must not link PkgConfig::EPOXY .*"
restore

# The command line links the static libraries, never libeikon.so (two copies of every global).
plant apps/CMakeLists.txt 'target_link_libraries(eikon PRIVATE eikon_api)'
expect "apps linking eikon_api fails" layering 1 \
    "eikon: apps/CMakeLists.txt:2: apps must not link eikon_api .*"
restore

plant "$pipeline_cpp" '#include "apps/commands.h"'
expect "pipeline including apps fails" layering 1 \
    "eikon: $pipeline_cpp:2: pipeline must not include apps/commands.h \(pipeline may include: .*\)"
restore

plant include/eikon/eikon.h '#include "core/scene.h"'
expect "a public header including core fails" layering 1 \
    "eikon: include/eikon/eikon.h:2: include must not include core/scene.h \(include may include: include\)"
restore

# ---- format ---------------------------------------------------------------------------------
# Formatted first, so that the planted line is the only difference whatever the tree's state.
(cd "$TREE" && find core sim render apps tests shaders/shared \( -name '*.h' -o -name '*.cpp' \) \
    -exec clang-format -i {} +)
expect "format passes on the formatted copy" format 0 'format: [0-9]+ files, .*'

plant "$core_cpp" 'int   x=1;'
expect "a badly formatted core file fails" format 1 \
    "eikon: $core_cpp: not formatted \(clang-format -i $core_cpp\)"
restore

echo "$passed passed, $failed failed"
((failed == 0))
