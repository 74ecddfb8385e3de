#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the test suite (unit, verification, validation and mpi labels) of an existing build.
# Usage: scripts/test.sh [--build-dir DIR] [extra ctest arguments, e.g. -L unit]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=build
if [ "${1:-}" = "--build-dir" ]; then build_dir="$2"; shift 2; fi
[ -d "$build_dir" ] || { echo "no build in $build_dir: run scripts/setup.sh first" >&2; exit 2; }
cmake --build "$build_dir" -j "$(nproc)"
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" "$@"
