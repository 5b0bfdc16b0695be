#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) in their own build
# directory and runs one of them for a while (issue 21 item 5).
# scripts/fuzz_ci.sh runs all four briefly, without sanitizers, in CI.
#   scripts/fuzz.sh TARGET SECONDS [libFuzzer options...]
#   TARGET: journal | mesh_read | triangulate | cad_import; SECONDS 0 only builds
# Seeds: examples/ and the journals of tests/ (journal), the mesh files of
# tests/framework/io/read/data (mesh_read), the CAD files of
# tests/framework/geometry/occ/data and, when present, ../shared/real-cad or
# $COOPERAGE_REAL_CAD (cad_import), fuzz/seeds/triangulate (triangulate). The corpus grows in
# build-fuzz/corpus/TARGET; a finding is saved in build-fuzz/artifacts/TARGET
# and makes the script exit non-zero. One process, one core.
#   COOPERAGE_FUZZ_BUILD_DIR=...   build directory (default: build-fuzz)
#   COOPERAGE_FUZZ_SANITIZERS=none libFuzzer alone, no ASan/UBSan (default:
#                                  address,undefined); use its own build dir
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
usage="usage: scripts/fuzz.sh journal|mesh_read|triangulate|cad_import SECONDS [libFuzzer options]"
target="${1:?$usage}"
seconds="${2:?$usage}"
shift 2
case "$target" in
  journal) max_len=65536 ;;
  mesh_read) max_len=262144 ;;
  triangulate) max_len=4096 ;;
  cad_import) max_len=524288 ;;
  *) echo "$usage" >&2; exit 2 ;;
esac
build="${COOPERAGE_FUZZ_BUILD_DIR:-$here/build-fuzz}"
if ! command -v clang++ >/dev/null; then
  echo "scripts/fuzz.sh needs clang: apt-get install clang libclang-rt-14-dev" >&2
  exit 2
fi
sanitize="${COOPERAGE_FUZZ_SANITIZERS:-address,undefined}"
sanitizers="-fsanitize=$sanitize -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
build_type=RelWithDebInfo
if [ "$sanitize" = none ]; then
  # Coverage instrumentation for libFuzzer only: a quick build for CI.
  sanitizers=""
  build_type=Release
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=$build_type \
    -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" \
    -DCMAKE_CXX_FLAGS="$sanitizers -fsanitize=fuzzer-no-link" \
    -DCMAKE_EXE_LINKER_FLAGS="$sanitizers" -DCMAKE_SHARED_LINKER_FLAGS="$sanitizers" \
    -DCOOPERAGE_BUILD_PYTHON=OFF \
    -DCOOPERAGE_BUILD_TESTS=OFF -DCOOPERAGE_BUILD_BENCH=OFF -DCOOPERAGE_BUILD_FUZZ=ON >/dev/null
fi
cmake --build "$build" -j2 --target "fuzz_$target"
[ "$seconds" = 0 ] && exit 0  # SECONDS 0: build only

seeds="$build/seeds/$target"
corpus="$build/corpus/$target"
artifacts="$build/artifacts/$target"
rm -rf "$seeds"
mkdir -p "$seeds" "$corpus" "$artifacts"
shopt -s nullglob globstar
case "$target" in
  journal) cp "$here"/examples/*.xml "$here"/tests/**/data/*.xml "$seeds"/ ;;
  mesh_read) cp "$here"/tests/framework/io/read/data/* "$seeds"/ ;;
  triangulate) cp "$here"/fuzz/seeds/triangulate/* "$seeds"/ ;;
  cad_import)
    cp "$here"/tests/framework/geometry/occ/data/*.* "$here"/tests/framework/geometry/occ/data/damaged/* "$seeds"/
    real_cad="${COOPERAGE_REAL_CAD:-$here/../shared/real-cad}"
    for f in "$real_cad"/*.st*p "$real_cad"/*.brep; do
      [ "$(stat -c %s "$f")" -le "$max_len" ] && cp "$f" "$seeds"/
    done
    ;;
esac

# Leaks are checked except where the CAD kernel keeps its caches until exit.
leaks=1
[ "$target" = cad_import ] && leaks=0
export ASAN_OPTIONS="detect_leaks=$leaks:abort_on_error=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
exec "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=60 -rss_limit_mb=4096 \
  -max_len="$max_len" -artifact_prefix="$artifacts/" -print_final_stats=1 "$@" "$corpus" "$seeds"
