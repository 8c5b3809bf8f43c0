#!/usr/bin/env bash
# Fails when an #include or a CMake link goes against the library direction, so that the layering
# is enforced, not just intended. One folder is one library:
#
#   core            math, fields, scenes; no GL, no simulation
#   sim             simulations, on core
#   render          GL, on core; loads the GLSL in shaders/
#   pipeline        what wires sim and render for a frame (input, backend, driver); on both
#   api             the public library (libeikon.so) behind include/eikon/; on pipeline and below
#   include         the public headers (include/eikon/); include nothing of the project's but
#                   each other, and every library may include them (eikon/error.h is the one
#                   exception type)
#   python          the Python module; the public API (include/) alone
#   apps            the command line; may use every library but api (the command line links the
#                   static libraries, not libeikon.so)
#   shaders/shared  the math compiled both as GLSL and as C++; includes no other project folder,
#                   so core may include it without pulling in GL (core/mesh_voxelize.cpp does: the
#                   CPU voxelizer runs the very code of the voxelize shaders)
#   shaders         GLSL programs; include only shaders/
#
# sim and render never include each other. tests/ may include anything and is not scanned;
# neither is shaders/test/ (fixtures of the shader loader's own tests, some broken on purpose).
# A library may use what lies below it, so sim may include shaders/shared as core does.
#
# GL: <epoxy/...>, <EGL/...>, <GL/...>, <GLFW/...> are forbidden in core, sim and shaders/shared,
# and core/sim CMakeLists may neither find nor link OpenGL, EGL, epoxy or GLFW. Every GL call lives
# in render: apps may include GLFW alone, because the viewer's window is render's
# GlfwWindowContext but its event loop (apps/cmd_view.cpp) polls GLFW for keys and the mouse; an
# <epoxy/...>, <EGL/...> or <GL/...> include in apps fails, and so does linking OpenGL, EGL or
# epoxy in apps/CMakeLists.txt. The root CMakeLists.txt finds those packages once for both render
# and apps (imported targets are visible only below the folder that found them), so it is not
# checked.
#
# Usage: scripts/check-layering.sh [ROOT]   (ROOT defaults to this repository)
set -euo pipefail
ROOT="${1:-$(dirname "$0")/..}"
cd "$ROOT"

declare -A MAY_INCLUDE=(
    [core]="core shaders/shared include"
    [sim]="sim core shaders/shared include"
    [render]="render core shaders/shared shaders include"
    [pipeline]="pipeline render sim core shaders/shared shaders include"
    [api]="api pipeline render sim core shaders/shared shaders include"
    [include]="include"
    [python]="python include"
    [apps]="apps pipeline render sim core shaders/shared shaders include"
    [shaders/shared]="shaders/shared"
    [shaders]="shaders shaders/shared"
)
GL_HEADER='^(epoxy|EGL|GL|GLES[0-9]*|GLFW|KHR)/'
APPS_GL_HEADER='^(epoxy|EGL|GL|GLES[0-9]*|KHR)/' # GLFW stays allowed: the viewer's events
violations=0

# Sets `lib` to the library that owns a repository-relative path, or empty outside the project.
library_of() {
    case "$1" in
        shaders/test/*) lib=tests ;;
        shaders/shared/*) lib=shaders/shared ;;
        shaders/*) lib=shaders ;;
        core/* | sim/* | render/* | pipeline/* | api/* | include/* | python/* | apps/* | tests/*)
            lib="${1%%/*}" ;;
        *) lib="" ;;
    esac
}

# Sets `norm` to a path with its "." and ".." segments folded (no file needs to exist).
normalize() {
    local IFS=/ part parts out=()
    read -ra parts <<<"$1"
    for part in "${parts[@]}"; do
        case "$part" in
            '' | .) ;;
            ..) # folds the segment before it, unless that is a ".." too
                if ((${#out[@]})) && [ "${out[-1]}" != .. ]; then
                    unset 'out[-1]'
                else
                    out+=(..)
                fi
                ;;
            *) out+=("$part") ;;
        esac
    done
    norm="${out[*]}"
}

violation() {
    echo "eikon: $*" >&2
    violations=$((violations + 1))
}

# ---- includes -------------------------------------------------------------------------------
mapfile -t files < <(
    find core sim render pipeline api include python apps -type f \( -name '*.h' -o -name '*.hpp' -o -name '*.cpp' \)
    find shaders -path shaders/test -prune -o -type f \
        \( -name '*.h' -o -name '*.comp' -o -name '*.glsl' -o -name '*.vert' -o -name '*.frag' \) \
        -print
)
# grep with no file names would read stdin and wait.
if ((${#files[@]} == 0)); then
    echo "eikon: no sources in core sim render apps shaders under $(pwd)" >&2
    exit 1
fi
include_re='^[[:space:]]*#[[:space:]]*include[[:space:]]*([<"])([^>"]+)[>"]'
while IFS= read -r hit; do
    file="${hit%%:*}" rest="${hit#*:}"
    line="${rest%%:*}" text="${rest#*:}"
    [[ "$text" =~ $include_re ]] || continue
    quote="${BASH_REMATCH[1]}" name="${BASH_REMATCH[2]}"
    library_of "$file"
    owner="$lib"
    if [ "$quote" = "<" ]; then
        # System headers are fine, except the GL ones below render.
        if [[ "$owner" =~ ^(core|sim|shaders/shared|pipeline|api|include|python)$ && "$name" =~ $GL_HEADER ]]; then
            violation "$file:$line: $owner must not include <$name> ($owner may include:" \
                "${MAY_INCLUDE[$owner]}; GL headers only in render, and GLFW in apps)"
        fi
        if [[ "$owner" == apps && "$name" =~ $APPS_GL_HEADER ]]; then
            violation "$file:$line: apps must not include <$name> (GL calls belong in render;" \
                "apps may include <GLFW/...> only, for the viewer's events)"
        fi
        continue
    fi
    # Resolved as the compilers do: beside the including file first, else from the include root
    # (the repository for C++, shaders/ for GLSL; render/shader_program.cpp resolves that way),
    # and the public headers from include/ ("eikon/error.h").
    root=.
    [[ "$file" =~ \.(comp|glsl|vert|frag)$ ]] && root=shaders
    beside="${file%/*}/$name"
    if [ -f "$beside" ]; then
        normalize "$beside"
    elif [ "$root" = . ] && [ ! -e "$name" ] && [ -f "include/$name" ]; then
        normalize "include/$name"
    else
        normalize "$root/$name"
    fi
    library_of "$norm"
    [ -n "$lib" ] || continue # outside the project's folders: a third-party header
    if [[ " ${MAY_INCLUDE[$owner]} " != *" $lib "* ]]; then
        violation "$file:$line: $owner must not include $norm" \
            "($owner may include: ${MAY_INCLUDE[$owner]})"
    fi
done < <(grep -nHE '^[[:space:]]*#[[:space:]]*include' "${files[@]}")

# ---- CMake link graph -----------------------------------------------------------------------
declare -A MUST_NOT_LINK=(
    [core]='^(eikon_sim|eikon_render)$|epoxy|egl|opengl|glfw|glew'
    [sim]='^eikon_render$|epoxy|egl|opengl|glfw|glew'
    [render]='^eikon_sim$'
    [pipeline]='^eikon_api$|epoxy|egl|opengl|glfw|glew'
    [api]='epoxy|egl|opengl|glfw|glew'
    [python]='^eikon_(core|sim|render|pipeline)$|epoxy|egl|opengl|glfw|glew'
    [apps]='^eikon_api$|epoxy|egl|opengl|glew'
)
declare -A MAY_LINK=(
    [core]="no other eikon library, no OpenGL/EGL/epoxy/GLFW"
    [sim]="eikon_core, no OpenGL/EGL/epoxy/GLFW"
    [render]="eikon_core, OpenGL/EGL/epoxy/GLFW"
    [pipeline]="eikon_sim, eikon_render and below, no OpenGL/EGL/epoxy/GLFW"
    [api]="eikon_pipeline and below, no OpenGL/EGL/epoxy/GLFW (they come inside eikon_render)"
    [python]="eikon_api alone (the public API), no OpenGL/EGL/epoxy/GLFW"
    [apps]="every eikon library but eikon_api, and GLFW, no OpenGL/EGL/epoxy"
)
for owner in core sim render pipeline api python apps; do
    cmake_file="$owner/CMakeLists.txt"
    [ -f "$cmake_file" ] || continue
    # Each find/link command as "line<TAB>arguments", joined over its continuation lines.
    while IFS=$'\t' read -r line command args; do
        read -ra items <<<"$args"
        # target_link_libraries' first argument is the target itself, not something it links.
        [ "$command" = target_link_libraries ] && items=("${items[@]:1}")
        for item in "${items[@]}"; do
            if [[ "${item,,}" =~ ${MUST_NOT_LINK[$owner]} ]]; then
                verb="find"
                [ "$command" = target_link_libraries ] && verb="link"
                violation "$cmake_file:$line: $owner must not $verb $item" \
                    "($owner may link: ${MAY_LINK[$owner]})"
                break # one line per command is enough
            fi
        done
    done < <(awk '
        { sub(/#.*/, "") } # comments
        !open && match(tolower($0), /^[ \t]*(target_link_libraries|find_package|pkg_[a-z_]+) *\(/) {
            open = 1; start = NR; text = ""
            command = tolower($0); sub(/^[ \t]*/, "", command); sub(/[ \t]*\(.*/, "", command)
            sub(/^[^(]*\(/, "")
        }
        open {
            text = text " " $0
            if (index($0, ")")) {
                sub(/\).*/, "", text); gsub(/[ \t]+/, " ", text)
                print start "\t" command "\t" text; open = 0
            }
        }' "$cmake_file")
done

((violations == 0)) || exit 1
echo "layering: ${#files[@]} files, no include crosses the library direction"
