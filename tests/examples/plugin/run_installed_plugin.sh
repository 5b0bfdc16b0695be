#!/usr/bin/env bash
# The third-party path of examples/plugin: install the build tree into a
# scratch prefix, build the example against it with find_package(Cooperage)
# (nothing from the build tree), and mesh a triangular prism with the
# installed `cooperage --plugin`: the plug-in must be listed with its
# library as origin and chosen for the triangle cap, and the mesh written.
set -euo pipefail
build_dir="$1"; source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
unset LD_LIBRARY_PATH COOPERAGE_PLUGIN_PATH

cmake -S "$source_dir/examples/plugin" -B "$work/plugin" \
      -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/plugin" -j2 >/dev/null
lib="$work/plugin/libcooperage_triprimitive.so"
test -f "$lib"

cd "$work"
cooperage="$prefix/bin/cooperage"
"$cooperage" --plugin "$lib" schemes | grep -E "^surface +triprimitive +$lib " >/dev/null \
  || { echo "triprimitive not listed with its library as origin"; exit 1; }
cat > prism.xml <<'XML'
<cooperage version="1">
  <plugin file="plugin/libcooperage_triprimitive.so"/>
  <geometry>
    <prism name="p" direction="0 0 1"><profile points="0 0 0, 2 0 0, 1 1.7320508075688772 0"/></prism>
  </geometry>
  <mesh size="0.3"/>
  <export file="prism.vtu"/>
</cooperage>
XML
"$cooperage" plan prism.xml | grep -E "^surface [0-9]+: triprimitive" >/dev/null \
  || { echo "the selector did not pick triprimitive for a triangle cap"; exit 1; }
"$cooperage" run prism.xml -q >/dev/null
test -s prism.vtu
echo "installed plugin ok"
