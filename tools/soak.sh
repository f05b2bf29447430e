#!/usr/bin/env bash
# Soak: dives replayed back to back through the vehicle's threaded runtime for an hour (by default) at 4x
# real time, with the resident memory and the scheduler's overruns and late ticks (tools/soak/README.md).
# Usage: tools/soak.sh [--minutes M] [--speed X] [DIVE.mcap...] [other deepnav-soak options]
# Without a dive it uses out-default/default.mcap (tools/dive-default.sh), else simulates a 60 s dive into out/soak-dive.mcap.
# Exit code: 0 memory flat, 1 growth over the limit (1 MiB), 2 a dive could not run.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${DEEPNAV_BUILD_DIR:-build}
if [[ ! -x "$build/bin/deepnav-soak" || ! -x "$build/bin/deepnav-sim" ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=toolchains/native.cmake >/dev/null
  cmake --build "$build" -j"$(nproc)" --target deepnav-soak deepnav-sim
fi
args=("$@")
has_dive=0
has_minutes=0
for a in "${args[@]}"; do
  [[ "$a" == *.mcap ]] && has_dive=1
  [[ "$a" == --minutes* ]] && has_minutes=1
done
[[ $has_minutes == 0 ]] && args=(--minutes 60 "${args[@]}")
if [[ $has_dive == 0 ]]; then
  if [[ -f out-default/default.mcap ]]; then
    args+=(out-default/default.mcap)
  else
    mkdir -p out
    if [[ ! -f out/soak-dive.mcap ]]; then
      sed 's/^duration_s: 120.0/duration_s: 60.0/' tools/sim/scenarios/default.yaml > out/soak-scenario.yaml
      "$build/bin/deepnav-sim" --scenario out/soak-scenario.yaml --out out/soak-dive.mcap
    fi
    args+=(out/soak-dive.mcap)
  fi
fi
exec "$build/bin/deepnav-soak" "${args[@]}"
