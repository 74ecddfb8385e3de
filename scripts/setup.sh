#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages hemoscale needs (only those missing), builds it, and runs the default
# example end to end. Usage: scripts/setup.sh [--no-example] [--build-dir DIR]
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
run_example=1
while [ $# -gt 0 ]; do
  case "$1" in
    --no-example) run_example=0 ;;
    --build-dir) build_dir="$2"; shift ;;
    *) echo "usage: scripts/setup.sh [--no-example] [--build-dir DIR]" >&2; exit 2 ;;
  esac
  shift
done

packages=(build-essential cmake git libeigen3-dev libopenmpi-dev openmpi-bin libhypre-dev libtomlplusplus-dev
          libcli11-dev nlohmann-json3-dev libfmt-dev libgtest-dev libgmock-dev libbenchmark-dev
          python3-matplotlib python3-numpy zlib1g-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

echo "== building in $build_dir"
werror=OFF
[ -n "${CI:-}" ] && werror=ON
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DHS_WERROR=$werror > "$build_dir.cmake.log" 2>&1 ||
  { cat "$build_dir.cmake.log"; exit 1; }
cmake --build "$build_dir" -j "$(nproc)"

if [ $run_example -eq 1 ]; then
  echo "== running the default example: cases/resolved/tube-poiseuille"
  "$build_dir/app/hemoscale" run cases/resolved/tube-poiseuille
fi
