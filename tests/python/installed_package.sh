#!/usr/bin/env bash
# `cmake --install` puts the Python package into <prefix>/lib/python3.X/
# dist-packages (for the default prefix /usr/local: Debian's site directory);
# installed into a scratch prefix, it imports and meshes from there alone.
set -euo pipefail
build_dir="$1"; source_dir="$2"; python="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
site="$(ls -d "$work"/prefix/lib/python3.*/dist-packages)"
cd "$work"
PYTHONPATH="$site" "$python" - "$source_dir/examples/part.step" "$site" <<'PY'
import sys
import cooperage
assert cooperage.__file__.startswith(sys.argv[2]), cooperage.__file__
mesh = cooperage.mesh(sys.argv[1], size=4)
assert len(mesh.cells["hexahedron"]) > 0
print("installed package ok:", mesh)
PY
