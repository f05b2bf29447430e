#!/usr/bin/env bash
# Sanitizer stage of the CI (tools/sanitize/README.md):
#   asan  builds everything (tests included, benchmarks excluded) with ASan+UBSan at -O1 in build-asan and
#         runs the whole ctest suite there, minus the tests listed in ASAN_EXCLUDE with their reasons;
#   tsan  builds only the threaded runtime's binaries and tests with TSan at -O1 in build-tsan and runs them.
#   asan-unit  the CI's share of asan within its time budget: deepnav and the unit tests (ctest label unit)
#         built with ASan+UBSan at -O1 in build-asan, and the unit tests run there.
# Any sanitizer report fails the test that produced it (halt_on_error / abort), so the stage passes only with
# zero findings. Usage: tools/sanitize/run.sh [asan] [asan-unit] [tsan]   (default: asan tsan)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
stages=("$@")
[[ ${#stages[@]} -eq 0 ]] && stages=(asan tsan)
jobs=$(nproc)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)

# Not run under ASan, each with its reason:
#  kernel_vm_drivers  boots Debian's kernel under QEMU/TCG (no KVM) and runs the driver tests inside; its
#                     guest is not the sanitized process, and the Release stage already runs it.
#  parsers_fuzz       the libFuzzer harnesses are built with clang under ASan+UBSan by the test itself;
#                     the Release stage already runs them.
ASAN_EXCLUDE='^(kernel_vm_drivers|parsers_fuzz)$'

# The threaded runtime: the loop, the real-time replay (crash_recording_test runs `deepnav replay
# --realtime`), the sensor and camera driver threads, the service (`deepnav run` as a child process, built
# with TSan too) and the soak (the loop on a faster clock).
TSAN_TARGETS=(deepnav deepnav-sim deepnav-soak live_loop_test crash_recording_test drivers_sensor_threads_test
  drivers_aravis_test service_alloc_test service_modbus_test service_notify_test service_restart_test
  service_sigterm_test service_udp_test service_validation_test soak_test)
TSAN_TESTS='^(live_loop_test|crash_recording_test|drivers_sensor_threads_test|drivers_aravis_test|service_(alloc|modbus|notify|restart|sigterm|udp|validation)_test|soak_test)\.'

configure() {  # build dir, sanitizer option
  cmake -S . -B "$1" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=toolchains/native.cmake \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O1 -g1 -DNDEBUG" \
    -DDEEPNAV_BUILD_BENCH=OFF "-D$2=ON" "${launcher[@]}" >/dev/null
}

for stage in "${stages[@]}"; do
  start=$(date +%s)
  case "$stage" in
    asan)
      configure build-asan DEEPNAV_SANITIZE
      cmake --build build-asan -j"$jobs"
      # --timeout 2400: stage2_replay_test (135 s in Release) exceeded 900 s under ASan at -O1.
      # detect_leaks: LeakSanitizer runs at each test process's exit. abort_on_error / halt_on_error: a
      # finding ends the test with a failure. The suppressions name third-party leaks only.
      ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=0" \
      UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
      LSAN_OPTIONS="suppressions=$PWD/tools/sanitize/lsan.supp:print_suppressions=0" \
        ctest --test-dir build-asan --output-on-failure -j"$jobs" --timeout 2400 -E "$ASAN_EXCLUDE"
      ;;
    asan-unit)
      configure build-asan DEEPNAV_SANITIZE
      cmake --build build-asan -j"$jobs" --target deepnav deepnav_unit_tests
      ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=0" \
      UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
      LSAN_OPTIONS="suppressions=$PWD/tools/sanitize/lsan.supp:print_suppressions=0" \
        ctest --test-dir build-asan --output-on-failure -j"$jobs" --timeout 1200 -L '^unit$'
      ;;
    tsan)
      configure build-tsan DEEPNAV_TSAN
      cmake --build build-tsan -j"$jobs" --target "${TSAN_TARGETS[@]}"
      TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/tools/sanitize/tsan.supp" \
        ctest --test-dir build-tsan --output-on-failure -j"$jobs" --timeout 900 -R "$TSAN_TESTS"
      ;;
    *) echo "usage: $0 [asan] [asan-unit] [tsan]" >&2; exit 2 ;;
  esac
  echo "sanitize: $stage stage passed in $(( $(date +%s) - start )) s"
done
