#!/usr/bin/env bash
# The main job on the seed's slider-crank with its flexible connecting rod
# (cases/slider_crank.yaml): build limber, then
#   1. limber modes   the rod's frequency table, modes.h5, modes_rod.vtu, mode-shape animations
#   2. limber run     1 s of the mechanism at 20 rev/s: results.h5 (reactions, deflection, ...)
#   3. limber render  two crank turns (0.5-0.6 s) in 20x slow motion, deformation x20: PNG
#                     frames, animation.mp4, vtk/scene.pvd for ParaView
#   4. limber report  report/index.html with the reaction-force plots
# Everything goes to out/slider_crank/ (or $1); the last line printed is the report's path.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build_dir=${LIMBER_BUILD_DIR:-$root/build}
limber="$build_dir/solver/app/limber"
case_file="$root/cases/slider_crank.yaml"
out=${1:-$root/out/slider_crank}
"$limber" modes "$case_file" -o "$out"
"$limber" run "$case_file" -o "$out"
"$limber" render "$out" --scale 20 --camera front --t0 0.5 --t1 0.6 --fps 600
"$limber" report "$out" --title "Seed slider-crank, flexible connecting rod"
