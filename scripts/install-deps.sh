#!/usr/bin/env bash
# Installs the Debian 12 packages limber needs, if missing.
# Usage: scripts/install-deps.sh [--tests]
#   (none)   what building `limber` and running the main job need (scripts/main-job.sh)
#   --tests  also what only the test suite and benchmarks need (scripts/run-tests.sh)
# Idempotent and non-interactive: does nothing when every package is present.
set -euo pipefail

with_tests=0
for arg in "$@"; do
  case "$arg" in
    --tests) with_tests=1 ;;
    -h|--help) sed -n '2,6s/^# \{0,1\}//p' "$0"; exit 0 ;;
    *) echo "install-deps: unknown argument '$arg' (expected --tests or nothing)" >&2; exit 2 ;;
  esac
done

# Build tools, the solver's libraries, rendering (VTK, headless EGL, PNG, ffmpeg for the videos)
# and the report's plotting library. Open MPI: limber sweep's ranks, and Debian's VTK charts
# module links it. hdf5-tools: h5dump and h5ls, to look into results.h5 and modes.h5. matio:
# limber linearize's MATLAB .mat files. pybind11 and Debian's python3 headers (python3-dev): the
# Python module `limber`; numpy: its arrays.
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev libopenblas-dev libarpack2-dev libsuitesparse-dev libsundials-dev
  libhdf5-dev hdf5-tools libmatio-dev
  libyaml-cpp-dev libcli11-dev libfmt-dev
  libvtk9-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libdeflate-dev
  openmpi-bin libopenmpi-dev
  libjs-dygraphs
  ffmpeg
  pybind11-dev python3-pybind11 python3-dev python3-numpy
)
# Only the tests and benchmarks: GoogleTest, Google Benchmark, and a headless browser that opens
# a report (tests/report/browser_test.cpp). Not ParaView's pvpython (python3-paraview), which
# tests/render/paraview_test.cpp uses when present: on Debian 12 it conflicts with python3-vtk9,
# a dependency of libvtk9-dev, so installing it makes apt remove VTK's headers. pytest: the
# Python module's tests (tests/python); mypy: its type stubs' check. debootstrap: the .deb's
# check in a fresh Debian 12 (tests/install/check_deb.sh).
test_packages=(
  libgtest-dev libgmock-dev libbenchmark-dev
  chromium
  python3-pytest mypy
  debootstrap
)
[ "$with_tests" -eq 0 ] || packages+=("${test_packages[@]}")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "limber: installing ${#missing[@]} Debian package(s): ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
