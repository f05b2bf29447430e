#!/usr/bin/env bash
# Sets up the machine (Debian packages), builds deepnav and runs the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
t_start=$(date +%s)
stage() { echo "test.sh: $1 ($(($(date +%s) - t_start)) s since start)"; }
tools/setup.sh
stage "native build"
# ccache: a rebuild of the same sources (another clone, the next CI run on this machine) takes minutes,
# not the 17 min of a cold build on 2 cores. CCACHE_BASEDIR makes the cache independent of where the
# clone lives (paths under it are hashed relative); the Release flags carry no -g, so no debug paths.
launcher=()
if command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="$PWD"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=toolchains/native.cmake "${launcher[@]}"
cmake --build build -j"$(nproc)"
# Stages ordered so the fastest failures come first (times on 2 cores: docs/tests-and-ci.md).
stage "stage 1/3: unit tests (native), amd64 package"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600 -L '^unit$'
rm -f build/deepnav_*_amd64.deb
(cd build && cpack -G DEB >/dev/null)
tools/package/check_deb.sh build/deepnav_*_amd64.deb amd64
# The vehicle's architecture: cross build, the unit tests under qemu-aarch64 (but the simulator's), the arm64
# .deb checked.
stage "stage 2/3: aarch64 build, unit tests under qemu, arm64 package"
JOBS="$(nproc)" tools/cross/build-aarch64.sh
stage "stage 3/3: integration tests, layout, fuzzers, kernel drivers in a VM"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600 -LE '^unit$'
stage "done"
# Sanitizer stage (issues 9 and 21, tools/sanitize/README.md), opt-in: DEEPNAV_SANITIZERS=unit runs the unit
# tests under ASan+UBSan (tools/sanitize/run.sh asan-unit), any other non-zero value the whole suite under
# ASan+UBSan (43 min alone on 2 cores) and the threaded runtime under TSan (open third-party reports).
case "${DEEPNAV_SANITIZERS:-0}" in
  0) ;;
  unit) tools/sanitize/run.sh asan-unit ;;
  *) tools/sanitize/run.sh ;;
esac
