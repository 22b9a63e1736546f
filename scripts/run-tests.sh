#!/usr/bin/env bash
# Builds limber with its tests, installs ParaView for the tests that open limber's output in
# it, and runs the whole suite with ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
"$root/scripts/install-paraview.sh"
build_dir=${LIMBER_BUILD_DIR:-$root/build}
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)"
