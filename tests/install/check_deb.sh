#!/usr/bin/env bash
# ctest Package.DebInstallsOnDebian12 (label package, issue 29): builds the .deb from the build
# tree with cpack and installs it in a fresh Debian 12 (scripts/check-deb-debian12.sh: `limber
# run` on a shipped case, `import limber`, limber.modes and limber.sweep there). It needs root
# (debootstrap, chroot, mount) and deb.debian.org (apt resolves the package's dependencies
# there); without either it reports SKIPPED with the reason (exit 77, the test's
# SKIP_RETURN_CODE). The Debian 12 root is made once by debootstrap and kept in ROOT, outside
# the build tree, so that later runs only install the package (docs/install.md gives the times).
# Usage: check_deb.sh BUILD_DIR SOURCE_DIR ROOT
set -euo pipefail
build_dir=$1
source_dir=$2
root=$3

skip() {
  echo "SKIPPED: $*"
  exit 77
}
[ "$(id -u)" -eq 0 ] || skip "not root: debootstrap, chroot and mount need it"
timeout 10 bash -c 'exec 3<> /dev/tcp/deb.debian.org/80' 2> /dev/null ||
  skip "deb.debian.org unreachable: apt resolves the package's dependencies there"

# The package, from what the build tree installs.
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
cpack --config "$build_dir/CPackConfig.cmake" -G DEB -B "$out" > "$out/cpack.log" ||
  { cat "$out/cpack.log"; exit 1; }
deb=$(ls "$out"/limber_*.deb)
echo "cpack: $(basename "$deb"), $(du -h "$deb" | cut -f1), $(($(date +%s) - start)) s"

# Installed and run in the Debian 12 root (made by debootstrap when missing), one test run at a
# time (two build trees share the root).
mkdir -p "$(dirname "$root")"
exec 9> "$root.lock"
flock 9
[ -x "$root/usr/bin/apt-get" ] || echo "no Debian 12 root in $root yet: debootstrap makes it (minutes)"
start=$(date +%s)
"$source_dir/scripts/check-deb-debian12.sh" "$deb" "$root"
echo "installed and checked in $(($(date +%s) - start)) s"
