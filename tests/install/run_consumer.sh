#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, then (1) runs the installed
# `cooperage` from an unrelated directory with no library path set (the
# README's `cmake --install build --prefix /opt/cooperage` case: RUNPATH is
# $ORIGIN-relative), and (2) configures, builds and runs tests/install/consumer
# against the prefix with find_package(Cooperage).
set -euo pipefail
build_dir="$1"; source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
unset LD_LIBRARY_PATH

# Every Cooperage library the command loads comes from the prefix, and no
# RUNPATH names the build tree or an absolute directory of ours.
libs="$(ldd "$prefix/bin/cooperage" | grep -F libcooperage_ || true)"
if [ -z "$libs" ] || grep -qv -F "$prefix/" <<<"$libs"; then
  echo "installed cooperage loads libraries from outside the prefix:"; echo "$libs"; exit 1
fi
for f in "$prefix"/bin/cooperage "$prefix"/lib*/libcooperage_*.so.*.*; do
  runpath="$(readelf -d "$f" | sed -n 's/.*R\(UN\)\?PATH.*\[\(.*\)\]/\2/p')"
  if grep -q -F "$build_dir" <<<"$runpath"; then echo "$f: RUNPATH names the build tree: $runpath"; exit 1; fi
done

cd "$work"
"$prefix/bin/cooperage" --help >/dev/null
"$prefix/bin/cooperage" mesh "$source_dir/examples/part.step" --size 4 -o part.vtu -q >/dev/null
test -s part.vtu

cmake -S "$source_dir/tests/install/consumer" -B "$work/consumer" \
      -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" -j2 >/dev/null
"$work/consumer/consumer" "$work"
