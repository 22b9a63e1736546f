#!/usr/bin/env bash
# Installs the .deb (cpack -G DEB) in a fresh Debian 12 and runs it there: `limber run` on a
# shipped case, `import limber`, limber.modes and limber.sweep (whose points run the installed
# executable). The Debian 12 is a minimal debootstrap in a folder (root, and the network to
# deb.debian.org: apt resolves the package's dependencies there as on a user's machine).
# Usage (as root): scripts/check-deb-debian12.sh build/limber_0.1.0_amd64.deb [ROOT]
#   ROOT  the Debian 12 folder (default build/deb12-root; made by debootstrap when missing)
set -euo pipefail
deb=$(realpath "$1")
root=${2:-$(dirname "$deb")/deb12-root}
if [ ! -x "$root/usr/bin/apt-get" ]; then
  command -v debootstrap > /dev/null || apt-get install -y debootstrap
  debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian
fi
cp "$deb" "$root/tmp/limber.deb"
chroot "$root" apt-get update -q
# --reinstall: a root kept from an earlier check may hold a package of the same version.
chroot "$root" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --reinstall /tmp/limber.deb
mount -t proc proc "$root/proc"
trap 'umount "$root/proc"' EXIT
chroot "$root" env -i PATH=/usr/bin:/bin HOME=/root bash -euc '
cd /tmp && rm -rf check && mkdir check && cd check
limber run /usr/share/limber/cases/slider_crank_rigid.yaml -o run --t-end 0.05 | tail -1
python3 -c "
import limber
r = limber.read_results(\"run\")
print(\"import limber\", limber.__version__, r.status, len(r.time), \"samples\")
m = limber.modes(\"/usr/share/limber/cases/slider_crank.yaml\")
print(\"modes:\", [round(x[\"frequency_hz\"], 2) for x in m[\"bodies\"][\"rod\"][\"modes\"] if x[\"kind\"] == \"normal\"])
s = limber.sweep(\"/usr/share/limber/cases/slider_crank_rigid.yaml\", over=[\"integrator=galpha\", \"step=1e-3\"], t_end=0.05, output=\"sweep\")
print(\"sweep:\", s[\"status\"], [(p[\"point\"], p[\"status\"]) for p in s[\"points\"]])
"'
echo "the .deb installs and runs on Debian $(cat "$root/etc/debian_version")"
