#!/usr/bin/env bash
# Installs every Debian 12 package deepnav needs to build, test and produce its report.
# Idempotent and non-interactive: safe to run on every CI job and every fresh machine.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git ccache
  libeigen3-dev libopencv-dev libopencv-contrib-dev liboctomap-dev
  libaravis-dev aravis-tools aravis-tools-cli libusb-1.0-0-dev
  libmodbus-dev libsystemd-dev libyaml-cpp-dev libcli11-dev libspdlog-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev libzstd-dev liblz4-dev libbz2-dev
  libnanoflann-dev libceres-dev
  clang-14 libclang-rt-14-dev
  python3 python3-numpy python3-matplotlib
  qemu-system-x86 busybox-static linux-image-amd64
  g++-aarch64-linux-gnu qemu-user-static mmdebstrap file   # CI's aarch64 stage (tools/cross/build-aarch64.sh)
  opencv-doc   # OpenCV's stereo checkerboard images, the real set of tests/unit/calib_checkerboard_test.cpp
)
# Node.js runs the independent MCAP reader in the tests; a machine that already has node
# (e.g. from NodeSource, whose nodejs conflicts with Debian's npm) keeps its own.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "setup: all Debian packages present"
fi

# The independent MCAP reader used by the tests (npm registry, pinned by package-lock.json).
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if command -v npm >/dev/null 2>&1 && [ -f "$here/mcapcheck/package.json" ]; then
  if [ ! -d "$here/mcapcheck/node_modules/@mcap/core" ]; then
    echo "setup: installing the independent MCAP reader (@mcap/core) with npm"
    (cd "$here/mcapcheck" && npm ci --no-audit --no-fund --loglevel=error) ||
      echo "setup: npm install failed; the independent-reader test will be skipped"
  fi
fi
