#!/usr/bin/env bash
# The whole aarch64 build in one command: installs the cross tools (g++-aarch64-linux-gnu,
# qemu-user-static, mmdebstrap) with apt if missing, makes the arm64 sysroot from Debian packages
# (tools/cross/make-sysroot.sh), cross-compiles deepnav and the unit tests with
# toolchains/aarch64-linux-gnu.cmake, runs the unit tests (ctest label "unit") under qemu-aarch64-static
# through ctest (CMAKE_CROSSCOMPILING_EMULATOR), then builds the arm64 .deb and checks it
# (tools/package/check_deb.sh). CI runs it through tools/test.sh; board/service/README.md has the times.
# Usage: tools/cross/build-aarch64.sh [ctest -R regex]   env: JOBS (default: all cores), BUILD_DIR, SYSROOT
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$root/build-aarch64}"
sysroot="${SYSROOT:-$root/build-aarch64-sysroot}"
jobs="${JOBS:-$(nproc)}"
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
# The unit tests only (label "unit", tests/CMakeLists.txt). Left out, because they cannot run under
# qemu-user: the integration tests (not built here: they drive x86 tools, serial ptys, vcan, fake GigE
# cameras in real time, and their ctest placeholders are *_NOT_BUILT), kernel_vm_drivers (boots a VM),
# parsers_fuzz (clang host tool) and layout_dependency_direction (a CMake script, same on every arch).
# Also left out under qemu, to keep CI within its budget (AARCH64_ALL_UNIT=1 runs them too), because the
# vehicle never runs their code: the simulator's tests (suites Sim*: tools/sim is a bench tool, not in the
# arm64 package; 492 s of the 1764 s the unit tests took under qemu), and CheckerboardOpencvDoc (182 s
# under qemu, 21 s native: OpenCV's own calibration on OpenCV's sample set; the calibrate code it
# drives is the one the CalibCharuco and CheckerboardView tests run under qemu).
exclude='^(Sim[A-Z][A-Za-z]*|CheckerboardOpencvDoc)\.'
[ "${AARCH64_ALL_UNIT:-0}" != 0 ] && exclude='^$'
status=0
ctest --test-dir "$build" --output-on-failure -j"$jobs" -L '^unit$' -E "$exclude" ${filter:+-R "$filter"} || status=$?
t3=$(date +%s)
# The package a vehicle installs: arm64, its Depends, unit, default board as conffiles, and the packaged
# binary (under qemu) validating the packaged board.
rm -f "$build"/deepnav_*_arm64.deb
(cd "$build" && cpack -G DEB >/dev/null) || status=1
"$root/tools/package/check_deb.sh" "$build/deepnav_$(sed -n 's/^project(deepnav VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")_arm64.deb" arm64 "$sysroot" || status=1
t4=$(date +%s)
echo "aarch64: sysroot $((t1 - t0)) s, build $((t2 - t1)) s, unit tests under qemu $((t3 - t2)) s, package $((t4 - t3)) s"
exit "$status"
