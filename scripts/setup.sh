#!/usr/bin/env bash
# Installs every Debian package Cooperage needs, then configures and builds.
# Idempotent and non-interactive; run as root on a fresh Debian 12.
#   scripts/setup.sh            install + configure + build (Release, -j2)
#   COOPERAGE_SKIP_APT=1 ...    skip the package step (already installed)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${COOPERAGE_BUILD_DIR:-$here/build}"

packages=(
  build-essential cmake pkg-config
  libocct-foundation-dev libocct-modeling-data-dev
  libocct-modeling-algorithms-dev libocct-data-exchange-dev
  libeigen3-dev libtbb-dev libtinyxml2-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libexodusii-dev libnetcdf-dev coinor-libcbc-dev libcli11-dev libopenmesh-dev
  libxml2-utils python3-meshio python3-gmsh python3-netcdf4
  pybind11-dev python3-pybind11 python3-numpy python3-pytest chromium
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${COOPERAGE_SKIP_APT:-0}" != 1 ] && [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE="${CMAKE_BUILD_TYPE:-Release}" -DCOOPERAGE_WERROR=ON
cmake --build "$build" -j2
