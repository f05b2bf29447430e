#!/usr/bin/env bash
# The default dive's job (the main job before the sea-trial family of tools/dive.sh): build deepnav,
# simulate the default dive (and its clear and murky variants), replay them through the full two-stage
# pipeline in the paper's test settings, print the paper's tables and write the report
# (out-default/, report-default/index.html).
#   tools/dive-default.sh [SEED]   (its figures: README, "The default dive")
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seed="${1:-1}"
jobs="$(nproc)"
start_s=$SECONDS

echo "== build"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=toolchains/native.cmake >/dev/null
cmake --build build -j"$jobs" --target deepnav deepnav-sim deepnav-figures

mkdir -p out-default report-default
log_dir=out-default
source tools/dive_jobs.sh

echo "== simulate the dives (seed $seed): default, clear, murky"
run_jobs \
  "sim-default:build/bin/deepnav-sim --scenario tools/sim/scenarios/default.yaml --seed $seed --out out-default/default.mcap" \
  "sim-clear:build/bin/deepnav-sim --scenario tools/sim/scenarios/clear.yaml --seed $seed --out out-default/clear.mcap" \
  "sim-murky:build/bin/deepnav-sim --scenario tools/sim/scenarios/murky.yaml --seed $seed --out out-default/murky.mcap"

echo "== replay through the two-stage pipeline: T_L2 (adaptive), EKF-all, T_L1, T_L3, clear, murky"
run_jobs \
  "tl2:build/bin/deepnav replay out-default/default.mcap --out out-default/tl2 --workspace-out out-default/tl2/workspace" \
  "all:build/bin/deepnav replay out-default/default.mcap --out out-default/all --set vision.vo_mode=all" \
  "tl1:build/bin/deepnav replay out-default/default.mcap --out out-default/tl1 --set vision.vo_mode=none" \
  "tl3:build/bin/deepnav replay out-default/default.mcap --out out-default/tl3 --set stage.fuse_markers_in_stage2=false" \
  "clear:build/bin/deepnav replay out-default/clear.mcap --out out-default/clear" \
  "murky:build/bin/deepnav replay out-default/murky.mcap --out out-default/murky"
echo
cat out-default/tl2.log | sed -n '2,20p'

echo "== figures: a stereo pair of the dive, its disparity, cloud planes, the stage-1 octomap"
build/bin/deepnav-figures out-default/default.mcap --time-s 56 --workspace out-default/tl2/workspace --out out-default/figures

echo "== tables"
/usr/bin/python3 tools/eval/paper_tables.py --run tl1=out-default/tl1 --run tl2=out-default/tl2 --run tl3=out-default/tl3 --run all=out-default/all \
  --run modality_clear=out-default/clear --run modality_default=out-default/tl2 --run modality_murky=out-default/murky --json out-default/tables.json |
  tee out-default/tables.md

echo "== report"
# Debian's interpreter: it has python3-matplotlib (a pyenv python3 earlier on PATH may not).
/usr/bin/python3 tools/eval/report.py --run out-default/tl2 --compare tl1=out-default/tl1 --compare all=out-default/all --compare tl3=out-default/tl3 \
  --tables out-default/tables.md --figures out-default/figures --out report-default
echo "report written to report-default/index.html ($((SECONDS - start_s)) s)"
