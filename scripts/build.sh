#!/usr/bin/env bash
# Installs the Debian packages (if missing), configures and builds limber in build/.
# Usage: scripts/build.sh [--tests] [extra cmake --build arguments, e.g. --target limber]
#   (none)   the packages `limber` needs; a new build/ is configured without the tests and
#            benchmarks (an existing one keeps its settings)
#   --tests  the test packages too; build/ is configured with the tests and benchmarks
#   LIMBER_BUILD_DIR  build folder (default build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tests=OFF
deps_args=()
if [ "${1:-}" = --tests ]; then
  tests=ON
  deps_args=(--tests)
  shift
fi
"$root/scripts/install-deps.sh" "${deps_args[@]}"
build_dir=${LIMBER_BUILD_DIR:-$root/build}
cache="$build_dir/CMakeCache.txt"
# The tests' packages (GoogleTest, Benchmark) are only required when the tests are configured.
if [ ! -f "$cache" ] ||
   { [ "$tests" = ON ] && ! grep -q '^LIMBER_BUILD_TESTS:BOOL=ON' "$cache"; } ||
   { [ "$tests" = ON ] && ! grep -q '^LIMBER_BUILD_BENCHMARKS:BOOL=ON' "$cache"; }; then
  cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DLIMBER_BUILD_TESTS="$tests" -DLIMBER_BUILD_BENCHMARKS="$tests"
fi
cmake --build "$build_dir" -j "$(nproc)" "$@"
