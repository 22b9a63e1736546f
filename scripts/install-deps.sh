#!/usr/bin/env bash
# Installs the Debian 12 packages limber builds and tests with.
# Idempotent and non-interactive: does nothing when every package is present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev libopenblas-dev libarpack2-dev libsuitesparse-dev libsundials-dev
  libhdf5-dev hdf5-tools
  libyaml-cpp-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libvtk9-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libdeflate-dev
  openmpi-bin libopenmpi-dev
  libjs-dygraphs
  ffmpeg
  chromium
)

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
