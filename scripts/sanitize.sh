#!/usr/bin/env bash
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc, RelWithDebInfo) in build-sanitize/, then run (issue 21 item 5). Not in
# the default CI path: the instrumented build and run take several times the
# normal ones. Any sanitizer report fails the test that triggered it.
#   scripts/sanitize.sh [ctest arguments...]     e.g. scripts/sanitize.sh -R journal
#   COOPERAGE_SANITIZE_BUILD_DIR=...   build directory (default: build-sanitize)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${COOPERAGE_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
if [ ! -f "$build/CMakeCache.txt" ]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" \
    -DCMAKE_SHARED_LINKER_FLAGS="$flags" -DCOOPERAGE_BUILD_BENCH=OFF
fi
cmake --build "$build" -j2
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$build"
ctest -j2 --output-on-failure --timeout 1800 "$@"
