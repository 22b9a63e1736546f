#!/usr/bin/env bash
# The main job: build limber, then run the modal analysis of the seed's slider-crank rod.
# Prints the frequency table and writes out/slider_crank/{modes.h5, modes_rod.vtu}.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build_dir=${LIMBER_BUILD_DIR:-$root/build}
"$build_dir/solver/app/limber" modes "$root/cases/slider_crank.yaml" -o "$root/out/slider_crank"
