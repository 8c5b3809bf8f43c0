#!/usr/bin/env bash
# Eikon as an installed library (issue 19): `cmake --install` the build into a temporary prefix,
# configure and build examples/cpp against it as a user's own project would (find_package(Eikon),
# Eikon::eikon), and run its Catch2 regression test, which renders through the installed
# libeikon.so and compares with a committed hash. The shaders are read from the prefix
# (EIKON_SHADER_DIR points there), as they are by a library installed far from its source tree.
# Where the Python module was built, the installed one is imported from the prefix and renders.
# Usage: tests/scripts/test_install.sh BUILD_DIR
set -euo pipefail
BUILD=$(realpath "$1")
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cmake --install "$BUILD" --prefix "$TMP/prefix" > "$TMP/install.log"
for f in include/eikon/eikon.h include/eikon/fields.h include/eikon/error.h \
    share/eikon/shaders/view.comp; do
    [ -e "$TMP/prefix/$f" ] || { echo "test_install: $f was not installed" >&2; exit 1; }
done
ls "$TMP"/prefix/lib*/libeikon.so* > /dev/null
ls "$TMP"/prefix/lib*/cmake/Eikon/EikonConfig.cmake > /dev/null
cmake -S "$ROOT/examples/cpp" -B "$TMP/example" -DCMAKE_PREFIX_PATH="$TMP/prefix" \
    -DCMAKE_BUILD_TYPE=Release > "$TMP/configure.log" || { cat "$TMP/configure.log"; exit 1; }
cmake --build "$TMP/example" -j 2 > "$TMP/build.log" || { cat "$TMP/build.log"; exit 1; }
# ldd's output is captured, not piped into `grep -q`: grep -q exits at the first match, and under
# pipefail the SIGPIPE that ldd may then get fails the check (it did, once, on CI).
links=$(ldd "$TMP/example/render_regression_test")
grep -q "$TMP/prefix/.*libeikon.so" <<< "$links" \
    || { echo "test_install: the example does not link the installed libeikon.so:" \
        "$(grep libeikon <<< "$links" || echo none)" >&2; exit 1; }
EIKON_SHADER_DIR="$TMP/prefix/share/eikon/shaders" "$TMP/example/render_regression_test"

if ls "$BUILD"/python/eikon*.so > /dev/null 2>&1; then
    module=$(ls "$TMP"/prefix/lib*/python3*/dist-packages/eikon*.so)
    links=$(ldd "$module")
    grep -q "$TMP/prefix/.*libeikon.so" <<< "$links" \
        || { echo "test_install: the Python module does not find the installed libeikon.so:" \
            "$(grep libeikon <<< "$links" || echo none)" >&2; exit 1; }
    PYTHONPATH=$(dirname "$module") /usr/bin/python3 -c "
import eikon, sys
assert eikon.__file__.startswith('$TMP/prefix'), eikon.__file__
s = eikon.Session.open('$ROOT/data/scenes/glass_sphere_fog.json', eikon.Device.CPU)
s.set_image_size(16, 12)
assert s.render(0).srgb8.sum() > 0
print('installed Python module renders')"
fi
