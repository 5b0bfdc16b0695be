#!/usr/bin/env bash
# Builds Cooperage if needed (Release, -j2) and runs every test with ctest;
# failures are printed with their output. Exit code: ctest's.
#   scripts/test.sh [ctest arguments...]     e.g. scripts/test.sh -R geometry
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${COOPERAGE_BUILD_DIR:-$here/build}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE="${CMAKE_BUILD_TYPE:-Release}" -DCOOPERAGE_WERROR=ON
fi
cmake --build "$build" -j2
cd "$build"
ctest -j2 --output-on-failure --timeout 300 "$@"
