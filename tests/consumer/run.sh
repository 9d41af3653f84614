#!/usr/bin/env bash
# A mesher's project built against the installed anisocert package (docs/api.md), as CI runs it
# (CTest test Api.ConsumerBuildsAgainstInstalledPackage):
#   1. anisocert installed into WORK/prefix: `cmake --install BUILD_DIR` when a build directory is
#      given (the main build: nothing is rebuilt, a few seconds), else configured from SOURCE_DIR in
#      WORK/anisocert-build (Release, no tests), built and installed (about 2 minutes on 2 cores);
#   2. tests/consumer configured with CMAKE_PREFIX_PATH=WORK/prefix (find_package(anisocert)),
#      built, and checked to see no header of the source tree;
#   3. docs/api.md's example (checked to be example.cpp) and mesher_test run (mesher_test writes its
#      Medit files in WORK), and the installed program certifies those files.
# Usage: run.sh SOURCE_DIR WORK_DIR [BUILD_DIR]   (the C++ compiler: $CXX, as for cmake)
# Exit 0 when the consumer builds and its test passes.
set -euo pipefail
src=$(cd "$1" && pwd)
work=$2
build=${3:-}
mkdir -p "$work"
work=$(cd "$work" && pwd)
prefix=$work/prefix
rm -rf "$prefix" "$work/consumer-build"

step() { echo "== $* ($(date +%T))"; }
start=$SECONDS
if [ -n "$build" ]; then
  step "install $build into $prefix"
  cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; exit 1; }
else
  step "configure, build and install $src (Release, no tests) into $prefix"
  cmake -S "$src" -B "$work/anisocert-build" -DCMAKE_BUILD_TYPE=Release -DANISOCERT_TESTS=OFF >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log"; exit 1; }
  cmake --build "$work/anisocert-build" -j "${JOBS:-2}" >"$work/build.log" 2>&1 || { tail -50 "$work/build.log"; exit 1; }
  echo "   $(grep -c 'warning:' "$work/build.log" || true) compiler warnings (in $work/build.log)"
  cmake --install "$work/anisocert-build" --prefix "$prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; exit 1; }
fi
echo "   $(find "$prefix" -type f | wc -l) files, $(du -sh "$prefix" | cut -f1) ($((SECONDS - start)) s)"

step "configure and build tests/consumer against $prefix"
cmake -S "$src/tests/consumer" -B "$work/consumer-build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >"$work/consumer-configure.log" 2>&1 || { cat "$work/consumer-configure.log"; exit 1; }
found=$(sed -n 's/^anisocert_DIR:PATH=//p' "$work/consumer-build/CMakeCache.txt")
case "$found" in
  "$prefix"/*) echo "   find_package(anisocert) found $found" ;;
  *) echo "FAIL: find_package(anisocert) found '$found', not the package in $prefix"; exit 1 ;;
esac
cmake --build "$work/consumer-build" >"$work/consumer-build.log" 2>&1 || { cat "$work/consumer-build.log"; exit 1; }
# The consumer sees the installed headers only: no path into the source tree (or a build tree in
# it) but its own folder and WORK.
leaks=$(grep -o "$src/[^ \"]*" "$work/consumer-build/compile_commands.json" |
  grep -v -e "^$src/tests/consumer/" -e "^$work/" || true)
if [ -n "$leaks" ]; then
  echo "FAIL: the consumer was compiled with paths into the source tree:"; echo "$leaks" | sort -u; exit 1
fi
echo "   built ($((SECONDS - start)) s)"

step "run docs/api.md's example and mesher_test"
# The example in docs/api.md is example.cpp, verbatim.
if ! diff <(awk '/^```cpp$/{on=1; next} /^```$/{if (on) exit} on' "$src/docs/api.md") "$src/tests/consumer/example.cpp"; then
  echo "FAIL: the example in docs/api.md differs from tests/consumer/example.cpp"; exit 1
fi
"$work/consumer-build/example"
echo "   the example: certified"
"$work/consumer-build/mesher_test" "$work"

step "the installed program on the mesh mesher_test wrote"
"$prefix/bin/anisocert" certify "$work/square.mesh" --metric "$work/square.sol" | tail -1
echo "   total $((SECONDS - start)) s"
