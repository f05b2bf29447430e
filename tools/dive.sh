#!/usr/bin/env bash
# The main job: build deepnav, simulate the sea-trial family (tools/sim/scenarios/sea-trial*.yaml: sea-grade
# sensors with systematic errors the board does not know, deep-sea image formation, a plume, the arm),
# replay each dive through the full two-stage pipeline in the paper's test settings and as dead
# reckoning, print the paper's tables over the seeds (mean ± std) and write the report.
#   tools/dive.sh                     the default matrix (README, "Main job": what it runs and how long)
#   DIVE_SEEDS="1 2 3" tools/dive.sh  other seeds
#   DIVE_VARIANTS="moderate murky clear" DIVE_RUNS_ALL=1 tools/dive.sh   the full matrix (README: its time)
# Outputs: out/tables.md (and .json), out/<variant>-s<seed>/<run>/summary.json, report/index.html. The
# recordings are deleted once replayed (about 2 GB each), but for out/sea-trial-s<first seed>.mcap (the
# figures' dive); DIVE_KEEP=1 keeps them all.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seeds=(${DIVE_SEEDS:-1 2})
variants=(${DIVE_VARIANTS:-moderate murky})
jobs="$(nproc)"
start_s=$SECONDS

# The paper's runs (README, "Main job"): the board as is is T_L2 (EKF-adaptive).
declare -A run_args=(
  [dr]="--set vision.vo_mode=none --set markers.enabled=false"
  [tl1]="--set vision.vo_mode=none"
  [tl2]=""
  [tl3]="--set stage.fuse_markers_in_stage2=false"
  [all]="--set vision.vo_mode=all"
)
# Which runs each variant gets: every run on moderate water; dead reckoning, T_L1 and T_L2 (the turbidity
# table) on the others, unless DIVE_RUNS_ALL=1. Rendering a 5-minute dive costs about 5 minutes of CPU:
# this is what fits the 20 minutes on two cores (README, "Main job").
runs_for() {
  if [[ "$1" != moderate && "${DIVE_RUNS_ALL:-0}" == 0 ]]; then echo "dr tl1 tl2"; else echo "dr tl1 tl2 tl3 all"; fi
}
scenario_of() {
  if [[ "$1" == moderate ]]; then echo tools/sim/scenarios/sea-trial.yaml; else echo "tools/sim/scenarios/sea-trial-$1.yaml"; fi
}

echo "== build"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=toolchains/native.cmake >/dev/null
cmake --build build -j"$jobs" --target deepnav deepnav-sim deepnav-figures
rm -rf out report
mkdir -p out report
echo "   seeds: ${seeds[*]}; variants: ${variants[*]}"

# Runs "name: command" specs, at most $jobs at a time, each logging to out/<name>.log; stops on failure.
run_jobs() {
  local pids=() names=()
  for spec in "$@"; do
    local name="${spec%%:*}" cmd="${spec#*:}"
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

# The replays of one recording, then the recording goes (unless it is the figures' dive or DIVE_KEEP=1).
replay_dive() {
  local tag="$1" variant="$2" seed="$3" specs=()
  for run in $(runs_for "$variant"); do
    local extra=""
    [[ "$run" == tl2 ]] && extra="--workspace-out out/$tag/tl2/workspace"
    specs+=("$tag-$run:build/bin/deepnav replay out/$tag.mcap --out out/$tag/$run ${run_args[$run]} $extra")
  done
  run_jobs "${specs[@]}"
  if [[ "$tag" != "sea-trial-s${seeds[0]}" && "${DIVE_KEEP:-0}" == 0 ]]; then rm -f "out/$tag.mcap"; fi
}

echo "== simulate and replay (a dive is simulated while the previous one is replayed)"
previous=()
for variant in "${variants[@]}"; do
  for seed in "${seeds[@]}"; do
    tag="$([[ $variant == moderate ]] && echo sea-trial || echo "sea-trial-$variant")-s$seed"
    echo "   simulating $tag"
    build/bin/deepnav-sim --scenario "$(scenario_of "$variant")" --board board/sim-sea/board.yaml --seed "$seed" \
      --no-truth-maps --out "out/$tag.mcap" >"out/sim-$tag.log" 2>&1 &
    sim_pid=$!
    if [ "${#previous[@]}" -gt 0 ]; then replay_dive "${previous[@]}"; fi
    if ! wait "$sim_pid"; then
      echo "simulating $tag failed; its log:" >&2
      tail -20 "out/sim-$tag.log" >&2
      exit 1
    fi
    echo "   simulated $tag ($((SECONDS - start_s)) s)"
    previous=("$tag" "$variant" "$seed")
  done
done
replay_dive "${previous[@]}"
echo
sed -n '2,20p' "out/sea-trial-s${seeds[0]}-tl2.log"

echo "== figures: a stereo pair of the sea trial, its disparity, cloud planes, the stage-1 octomap"
build/bin/deepnav-figures "out/sea-trial-s${seeds[0]}.mcap" --time-s 230 \
  --workspace "out/sea-trial-s${seeds[0]}/tl2/workspace" --out out/figures

echo "== tables"
# One set of tables per water variant (its runs over the seeds), then the modality table across them.
{
  for variant in "${variants[@]}"; do
    prefix="$([[ $variant == moderate ]] && echo sea-trial || echo "sea-trial-$variant")"
    echo "### Sea trial, $variant water (seeds ${seeds[*]})"
    echo
    args=()
    for run in $(runs_for "$variant"); do args+=(--run "$run=out/$prefix-s*/$run"); done
    /usr/bin/python3 tools/eval/paper_tables.py "${args[@]}" --json "out/tables-$variant.json"
  done
  echo "### Modality against turbidity (EKF-adaptive, seeds ${seeds[*]})"
  echo
  args=()
  for variant in "${variants[@]}"; do
    prefix="$([[ $variant == moderate ]] && echo sea-trial || echo "sea-trial-$variant")"
    args+=(--run "modality_$variant=out/$prefix-s*/tl2")
  done
  /usr/bin/python3 tools/eval/paper_tables.py "${args[@]}" --json out/tables-modality.json
} | tee out/tables.md

echo "== report"
# Debian's interpreter: it has python3-matplotlib (a pyenv python3 earlier on PATH may not).
s1="out/sea-trial-s${seeds[0]}"
/usr/bin/python3 tools/eval/report.py --run "$s1/tl2" --compare "dr=$s1/dr" --compare "tl1=$s1/tl1" \
  --compare "all=$s1/all" --compare "tl3=$s1/tl3" --tables out/tables.md --figures out/figures --out report
echo "report written to report/index.html ($((SECONDS - start_s)) s); disk: $(du -sh out | cut -f1)"
