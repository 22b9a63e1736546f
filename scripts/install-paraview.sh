#!/usr/bin/env bash
# Installs ParaView 5.11 for the tests that open limber's output in ParaView itself
# (tests/render/paraview_check.py), and for users who want pvpython beside limber's build;
# with xvfb, since Debian's pvbatch draws through X and a test saves a screenshot with it.
# Debian's `paraview` package brings the libraries and pvbatch; pvpython and the Python modules
# come in `python3-paraview`, which conflicts with python3-vtk9, a dependency of libvtk9-dev
# that limber builds with. So python3-paraview is unpacked beside, into
# /usr/local/lib/limber/paraview (its usr/ tree), next to a copy of pvbatch: ParaView finds its
# Python modules relative to the program it runs. /usr/local/bin/pvpython and pvbatch run them.
# Idempotent and non-interactive.
set -euo pipefail

prefix=/usr/local/lib/limber/paraview
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive

missing=()
for p in paraview xvfb xauth; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "limber: installing ${missing[*]} (ParaView: about 70 MB to download)"
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

version=$(dpkg-query -W -f='${Version}' paraview)
stamp="$prefix/.version"
if [ "$(cat "$stamp" 2>/dev/null)" != "$version" ]; then
  echo "limber: unpacking python3-paraview $version into $prefix"
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  # apt-get downloads as the _apt user when that user may write the folder.
  if [ "$(id -u)" -eq 0 ] && id _apt > /dev/null 2>&1; then chown _apt "$work"; fi
  (cd "$work" && apt-get download -qq "python3-paraview=$version")
  dpkg-deb -x "$work"/python3-paraview_*.deb "$work/root"
  cp /usr/bin/pvbatch "$work/root/usr/bin/pvbatch"
  "${sudo_cmd[@]}" rm -rf "$prefix"
  "${sudo_cmd[@]}" mkdir -p "$(dirname "$prefix")"
  "${sudo_cmd[@]}" cp -a "$work/root/usr" "$prefix"
  echo "$version" | "${sudo_cmd[@]}" tee "$stamp" > /dev/null
fi

for tool in pvpython pvbatch; do
  "${sudo_cmd[@]}" tee "/usr/local/bin/$tool" > /dev/null <<WRAPPER
#!/bin/sh
# ParaView's $tool with the Python modules of python3-paraview (limber's scripts/install-paraview.sh).
exec $prefix/bin/$tool "\$@"
WRAPPER
  "${sudo_cmd[@]}" chmod 755 "/usr/local/bin/$tool"
done
