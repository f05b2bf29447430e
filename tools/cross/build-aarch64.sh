#!/usr/bin/env bash
# The whole aarch64 build in one command: installs the cross tools (g++-aarch64-linux-gnu,
# qemu-user-static, mmdebstrap) with apt if missing, makes the arm64 sysroot from Debian packages
# (tools/cross/make-sysroot.sh), cross-compiles deepnav and the unit tests with
# toolchains/aarch64-linux-gnu.cmake, and runs the unit tests under qemu-aarch64-static through ctest
# (CMAKE_CROSSCOMPILING_EMULATOR). Heavy on a small machine (see board/service/README.md for the
# measured time); not part of CI.
# Usage: tools/cross/build-aarch64.sh [ctest -R regex]   env: JOBS (default 1), BUILD_DIR, SYSROOT
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$root/build-aarch64}"
sysroot="${SYSROOT:-$root/build-aarch64-sysroot}"
jobs="${JOBS:-1}"
filter="${1:-}"

need=()
for p in g++-aarch64-linux-gnu qemu-user-static mmdebstrap; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need+=("$p")
done
if [ "${#need[@]}" -gt 0 ]; then
  sudo_cmd=(); [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${need[@]}"
fi

t0=$(date +%s)
"$root/tools/cross/make-sysroot.sh" "$sysroot"
t1=$(date +%s)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_TOOLCHAIN_FILE="$root/toolchains/aarch64-linux-gnu.cmake" -DDEEPNAV_SYSROOT="$sysroot" \
  -DDEEPNAV_BUILD_BENCH=OFF "${launcher[@]}"
ninja -C "$build" -j"$jobs" deepnav deepnav_unit_tests
t2=$(date +%s)
file "$build/bin/deepnav"
# Unit tests only: integration tests are not built here (their placeholders are *_test_NOT_BUILT), and
# the fuzzers are host tools.
status=0
ctest --test-dir "$build" --output-on-failure -j"$jobs" ${filter:+-R "$filter"} \
  -E '_test(\.|_NOT_BUILT$)|^parsers_fuzz$' || status=$?
t3=$(date +%s)
echo "aarch64: sysroot $((t1 - t0)) s, build $((t2 - t1)) s, unit tests under qemu $((t3 - t2)) s"
exit "$status"
