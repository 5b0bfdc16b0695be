#!/usr/bin/env bash
# The short fuzz run of CI (issue 21 item 5): the four libFuzzer targets,
# built with clang and libFuzzer's coverage instrumentation but no
# sanitizers (a sanitizer build does not fit CI's time; scripts/fuzz.sh runs
# them with ASan + UBSan by hand), two at a time. Each runs a fixed number
# of inputs from its seeds with a fixed seed, so a run that passes here
# passes in CI whatever the machine's speed (a time limit alone made CI
# reach further than the last local run, and fail on a finding nobody had
# seen); SECONDS only caps a target that runs slower than expected. Any crash, timeout, out-of-memory or failed
# invariant is a finding: it is saved in build-fuzz-ci/artifacts/TARGET and
# the script exits 1.
#   scripts/fuzz_ci.sh [SECONDS]      (cap per target, default 60)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
export COOPERAGE_FUZZ_SANITIZERS=none
export COOPERAGE_FUZZ_BUILD_DIR="${COOPERAGE_FUZZ_CI_BUILD_DIR:-$here/build-fuzz-ci}"
build="$COOPERAGE_FUZZ_BUILD_DIR"
targets=(journal mesh_read triangulate cad_import)
# Inputs per target: about 20 s each on a CI core (2026-12-02: journal
# 51,000 inputs/s, mesh_read 7,700/s, triangulate 32,000/s, cad_import 1.3/s).
declare -A runs_of=([journal]=1000000 [mesh_read]=150000 [triangulate]=600000 [cad_import]=25)

start=$(date +%s)
# Configure and build every target once (fuzz.sh builds only its own).
"$here/scripts/fuzz.sh" journal 0
cmake --build "$build" -j2 --target "${targets[@]/#/fuzz_}"
echo "fuzz_ci: built in $(( $(date +%s) - start )) s"

logs="$build/logs"
mkdir -p "$logs"
run() {
  # A fresh corpus each time: the run depends only on the seeds and -seed.
  rm -rf "$build/corpus/$1"
  "$here/scripts/fuzz.sh" "$1" "$seconds" -seed=1 -runs="${runs_of[$1]}" >"$logs/$1.log" 2>&1
}
status=0
for pair in "journal mesh_read" "triangulate cad_import"; do
  pids=()
  for t in $pair; do run "$t" & pids+=("$!:$t"); done
  for p in "${pids[@]}"; do
    t="${p#*:}"
    if wait "${p%%:*}"; then
      runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$logs/$t.log" | grep -o '[0-9]*$' || echo "?")
      echo "fuzz_ci: $t: ${runs} runs of ${runs_of[$t]}, no finding"
    else
      echo "fuzz_ci: $t: FINDING (log $logs/$t.log, artifacts $build/artifacts/$t)"
      tail -40 "$logs/$t.log"
      status=1
    fi
  done
done
echo "fuzz_ci: done in $(( $(date +%s) - start )) s"
exit $status
