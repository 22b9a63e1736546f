#!/usr/bin/env bash
# Installs what the fuzz build needs on top of scripts/install-deps.sh: Debian's clang, whose
# compiler-rt (libclang-rt-14-dev, a dependency) holds libFuzzer, ASan and UBSan. Not part of CI
# (the fuzz regression inputs run in the normal GCC build's tests); used by
# scripts/fuzz-case-reader.sh. Idempotent.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
if dpkg-query -W -f='${Status}' clang 2>/dev/null | grep -q "install ok installed"; then
  exit 0
fi
echo "limber: installing clang (fuzz build)"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends clang
