#!/usr/bin/env bash
# Installs the Debian dependencies (if missing), configures and builds limber in build/.
# Usage: scripts/build.sh [extra cmake --build arguments]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
build_dir=${LIMBER_BUILD_DIR:-$root/build}
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build_dir" -j "$(nproc)" "$@"
