#!/usr/bin/env bash
# Installs the packages the tests need too (scripts/install-deps.sh --tests, and ParaView by
# scripts/install-paraview.sh for the tests that open limber's output in it), builds every
# target, tests and benchmarks included, and runs the whole suite with ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh" --tests
"$root/scripts/install-paraview.sh"
build_dir=${LIMBER_BUILD_DIR:-$root/build}
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)"
