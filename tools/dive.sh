#!/usr/bin/env bash
# The main job: build deepnav, simulate the default dive (and its clear and murky variants), replay them
# through the full two-stage pipeline in the paper's test settings, print the paper's tables and write
# the report (report/index.html).
#   tools/dive.sh [SEED]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seed="${1:-1}"
jobs="$(nproc)"
start_s=$SECONDS

echo "== build"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=toolchains/native.cmake >/dev/null
cmake --build build -j"$jobs" --target deepnav deepnav-sim deepnav-figures

mkdir -p out report
# Runs "name: command..." jobs, at most $jobs at a time, each logging to out/<name>.log; stops on failure.
run_jobs() {
  local pids=() names=()
  for spec in "$@"; do
    local name="${spec%%:*}" cmd="${spec#*:}"
    echo "   started $name"
    bash -c "$cmd" >"out/$name.log" 2>&1 &
    pids+=($!)
    names+=("$name")
    if [ "${#pids[@]}" -ge "$jobs" ]; then
      wait_jobs; pids=(); names=()
    fi
  done
  wait_jobs
}
wait_jobs() {
  for i in "${!pids[@]}"; do
    if ! wait "${pids[$i]}"; then
      echo "${names[$i]} failed; its log:" >&2
      tail -20 "out/${names[$i]}.log" >&2
      exit 1
    fi
    echo "   done ${names[$i]} ($((SECONDS - start_s)) s)"
  done
}

echo "== simulate the dives (seed $seed): default, clear, murky"
run_jobs \
  "sim-default:build/bin/deepnav-sim --scenario tools/sim/scenarios/default.yaml --seed $seed --out out/default.mcap" \
  "sim-clear:build/bin/deepnav-sim --scenario tools/sim/scenarios/clear.yaml --seed $seed --out out/clear.mcap" \
  "sim-murky:build/bin/deepnav-sim --scenario tools/sim/scenarios/murky.yaml --seed $seed --out out/murky.mcap"

echo "== replay through the two-stage pipeline: T_L2 (adaptive), EKF-all, T_L1, T_L3, clear, murky"
run_jobs \
  "tl2:build/bin/deepnav replay out/default.mcap --out out/tl2 --workspace-out out/tl2/workspace" \
  "all:build/bin/deepnav replay out/default.mcap --out out/all --set vision.vo_mode=all" \
  "tl1:build/bin/deepnav replay out/default.mcap --out out/tl1 --set vision.vo_mode=none" \
  "tl3:build/bin/deepnav replay out/default.mcap --out out/tl3 --set stage.fuse_markers_in_stage2=false" \
  "clear:build/bin/deepnav replay out/clear.mcap --out out/clear" \
  "murky:build/bin/deepnav replay out/murky.mcap --out out/murky"
echo
cat out/tl2.log | sed -n '2,20p'

echo "== figures: a stereo pair of the dive, its disparity, cloud planes, the stage-1 octomap"
build/bin/deepnav-figures out/default.mcap --time-s 56 --workspace out/tl2/workspace --out out/figures

echo "== tables"
/usr/bin/python3 tools/eval/paper_tables.py --run tl1=out/tl1 --run tl2=out/tl2 --run tl3=out/tl3 --run all=out/all \
  --run modality_clear=out/clear --run modality_default=out/tl2 --run modality_murky=out/murky --json out/tables.json |
  tee out/tables.md

echo "== report"
# Debian's interpreter: it has python3-matplotlib (a pyenv python3 earlier on PATH may not).
/usr/bin/python3 tools/eval/report.py --run out/tl2 --compare tl1=out/tl1 --compare all=out/all --compare tl3=out/tl3 \
  --tables out/tables.md --figures out/figures --out report
echo "report written to report/index.html ($((SECONDS - start_s)) s)"
