#!/usr/bin/env bash
# Installs every build and test dependency from Debian 12's archive. Idempotent: apt-get only
# installs what is missing. Needs root (or sudo).
set -euo pipefail

PACKAGES=(
    build-essential cmake pkg-config
    libopenvdb-dev libopenvdb-tools libnanovdb-dev libboost-iostreams-dev libtbb-dev
    libopenmesh-dev libeigen3-dev
    libglm-dev libglfw3-dev libepoxy-dev libegl-dev libgl-dev
    libimgui-dev  # the viewer's panel (Dear ImGui with its GLFW and OpenGL 3 backends)
    libegl-mesa0 libgl1-mesa-dri libglx-mesa0 xvfb xauth
    nlohmann-json3-dev libcli11-dev libpng-dev libopenexr-dev
    zlib1g-dev  # gzip-encoded NRRD scans (core/scan_volume.cpp)
    catch2
    python3-matplotlib  # scripts/plot_advection_bench.py (run with /usr/bin/python3)
    pybind11-dev python3-dev python3-numpy python3-pytest python3-openvdb  # python/: `import eikon`,
    # its pytest suite and the pyopenvdb interplay
    clang-format  # scripts/check-format.sh
    glslang-tools  # tests/render/test_glslang.cpp: every shader variant through the Khronos reference compiler
    slurm-wlm munge  # tests/scripts/test_slurm_farm.sh: a one-node Slurm on 127.0.0.1
    # scripts/fuzz.sh: clang with libFuzzer and the sanitizer runtimes, and llvm-symbolizer for
    # readable stacks in a finding's report.
    clang-14 libclang-rt-14-dev llvm-14
)

missing=()
for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#PACKAGES[@]} packages present"
    exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
