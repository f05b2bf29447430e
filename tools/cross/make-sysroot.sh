#!/usr/bin/env bash
# Builds the arm64 sysroot for the aarch64 cross build from Debian 12 packages: mmdebstrap
# --variant=extract unpacks the -dev packages deepnav builds against, and their dependencies, without
# running anything of arm64; absolute symlinks are then made relative so that they resolve inside the
# sysroot. Usage: tools/cross/make-sysroot.sh [SYSROOT]   (default: build-aarch64-sysroot/)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
sysroot="${1:-$root/build-aarch64-sysroot}"
mirror="${DEBIAN_MIRROR:-http://deb.debian.org/debian}"

# What deepnav links (tools/setup.sh's -dev packages, minus the benchmarks) plus the C/C++ runtime.
packages=(
  libc6-dev libstdc++-12-dev
  libeigen3-dev libopencv-dev libopencv-contrib-dev liboctomap-dev
  libaravis-dev libusb-1.0-0-dev libmodbus-dev libyaml-cpp-dev libcli11-dev libspdlog-dev libfmt-dev
  libgtest-dev libgmock-dev libzstd-dev liblz4-dev libbz2-dev libnanoflann-dev libceres-dev
)
# Without maintainer scripts, update-alternatives never ran: make the links it would have made for the
# reference BLAS and LAPACK (libopencv_core needs libblas.so.3 and liblapack.so.3).
alternatives() {
  local lib="$1/usr/lib/aarch64-linux-gnu"
  for name in blas lapack; do
    for so in "lib$name.so.3" "lib$name.so"; do
      if [ ! -e "$lib/$so" ] && [ -e "$lib/$name/$so" ]; then ln -s "$name/$so" "$lib/$so"; fi
    done
  done
}

# The marker holds the package list it was made from: a sysroot made before a package was added is
# made again (CI reuses the clone's directory only within one run, a developer's across edits).
stamp="${packages[*]}"
if [ -f "$sysroot/.deepnav-sysroot" ] && [ "$(cat "$sysroot/.deepnav-sysroot")" = "$stamp" ]; then
  alternatives "$sysroot"
  echo "make-sysroot: $sysroot is up to date (remove it to rebuild)"
  exit 0
fi
rm -rf "$sysroot"
include="$(IFS=,; echo "${packages[*]}")"
mmdebstrap --variant=extract --architectures=arm64 --include="$include" --quiet bookworm "$sysroot" "$mirror"

# Absolute symlinks (e.g. /usr/lib/aarch64-linux-gnu/libfoo.so -> /lib/...) point at the host; rewrite
# them relative to the sysroot. Debian 12 is merged-/usr: give the sysroot the same /lib, /bin links.
for d in lib bin sbin; do
  if [ -d "$sysroot/$d" ] && [ ! -L "$sysroot/$d" ]; then
    cp -a "$sysroot/$d/." "$sysroot/usr/$d/" && rm -rf "${sysroot:?}/$d"
  fi
  [ -e "$sysroot/$d" ] || ln -s "usr/$d" "$sysroot/$d"
done
find "$sysroot" -type l -lname '/*' | while read -r link; do
  target="$(readlink "$link")"
  ln -sfn "$(realpath -m --relative-to="$(dirname "$link")" "$sysroot$target")" "$link"
done
alternatives "$sysroot"
echo "$stamp" >"$sysroot/.deepnav-sysroot"
du -sh "$sysroot"
