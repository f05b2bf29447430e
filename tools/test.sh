#!/usr/bin/env bash
# Sets up the machine (Debian packages), builds deepnav and runs the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
tools/setup.sh
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
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600
# Sanitizer stage (issue 9, tools/sanitize/README.md): the whole suite under ASan+UBSan, the threaded
# runtime under TSan; any finding fails. Opt-in (DEEPNAV_SANITIZERS=1): the ASan+UBSan suite alone took
# 43 min on this 2-core machine (dive tests 4-12x slower), beyond the CI budget beside the Release stage,
# and the TSan stage still reports races inside uninstrumented libraries (OpenCV's TBB pool, GLib).
if [[ "${DEEPNAV_SANITIZERS:-0}" != 0 ]]; then tools/sanitize/run.sh; fi
