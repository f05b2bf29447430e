#!/usr/bin/env bash
# The main job: build deepnav, simulate the sea-trial family (tools/sim/scenarios/sea-trial*.yaml: sea-grade
# sensors with systematic errors the board does not know, deep-sea image formation, a plume, the arm),
# replay each dive through the full two-stage pipeline in the paper's test settings and as dead
# reckoning, print the paper's tables over the seeds (mean ± std) and write the report.
#   tools/dive.sh            the default matrix, sized for 20 minutes on 2 cores (docs/results.md, "Main job")
#   DIVE_SEEDS="3 4 5" DIVE_OTHER_SEEDS="3 4 5" DIVE_VARIANTS="moderate murky clear" DIVE_RUNS_ALL=1 tools/dive.sh
#                            a wider matrix (about 9 minutes of the 2 cores per 5-minute dive with all runs)
# Outputs: out/tables.md (and out/tables-*.json), out/<dive>/<run>/summary.json, report/index.html. The
# recordings (about 1.3 GB each) are deleted once replayed, but for out/sea-trial-s<first seed>.mcap
# (the figures' dive); DIVE_KEEP=1 keeps them all, and DIVE_REUSE=1 replays those in out/ without simulating
# them again.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# Seeds 1 and 2 are the development seeds (what the estimator was tuned and debugged on); the tables
# come from seeds it never saw.
seeds=(${DIVE_SEEDS:-3 4})               # the moderate sea trial
other_seeds=(${DIVE_OTHER_SEEDS:-3})     # the other waters
variants=(${DIVE_VARIANTS:-moderate murky})
jobs="$(nproc)"
start_s=$SECONDS

# The paper's runs (docs/results.md, "Main job"): the board as is is T_L2 (EKF-adaptive).
declare -A run_args=(
  [dr]="--set vision.vo_mode=none --set markers.enabled=false"
  [tl1]="--set vision.vo_mode=none"
  [tl2]=""
  [tl3]="--set stage.fuse_markers_in_stage2=false"
  [all]="--set vision.vo_mode=all"
)
# Every run on the moderate water; dead reckoning and T_L2 (the turbidity table) on the others, unless
# DIVE_RUNS_ALL=1. Longest first (EKF-all runs both VO on every pair), so the pool's tail is short.
# Rendering a 5-minute sea trial costs about 5.5 minutes of one core.
runs_for() {
  if [[ "$1" != moderate && "${DIVE_RUNS_ALL:-0}" == 0 ]]; then echo "tl2 dr"; else echo "all tl2 tl3 tl1 dr"; fi
}
prefix_of() { if [[ "$1" == moderate ]]; then echo sea-trial; else echo "sea-trial-$1"; fi; }
seeds_of() { if [[ "$1" == moderate ]]; then echo "${seeds[*]}"; else echo "${other_seeds[*]}"; fi; }

echo "== build"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=toolchains/native.cmake >/dev/null
cmake --build build -j"$jobs" --target deepnav deepnav-sim deepnav-figures
if [[ "${DIVE_REUSE:-0}" == 1 && -d out ]]; then
  find out -mindepth 1 -maxdepth 1 ! -name '*.mcap' -exec rm -rf {} +
  rm -rf report
else
  rm -rf out report
fi
mkdir -p out report
log_dir=out
start_s=$SECONDS

# A pool of "name|after|command" jobs: at most $jobs run at once; a job starts when the job it names in
# "after" (if any) has finished, the first ready one in the list first. Stops on the first failure.
run_pool() {
  local queue=("$@") running=0 pid i name after cmd
  declare -A finished=() name_of=()
  while (( ${#queue[@]} > 0 || running > 0 )); do
    for i in "${!queue[@]}"; do
      (( running < jobs )) || break
      IFS='|' read -r name after cmd <<<"${queue[$i]}"
      [[ -z "$after" || -n "${finished[$after]:-}" ]] || continue
      bash -c "$cmd" >"$log_dir/$name.log" 2>&1 &
      name_of[$!]="$name"
      running=$((running + 1))
      unset "queue[$i]"
    done
    queue=("${queue[@]}")
    if ! wait -n -p pid; then
      echo "${name_of[$pid]} failed; its log:" >&2
      tail -20 "$log_dir/${name_of[$pid]}.log" >&2
      exit 1
    fi
    finished[${name_of[$pid]}]=1
    running=$((running - 1))
    echo "   done ${name_of[$pid]} ($((SECONDS - start_s)) s)"
  done
}

dives=()
for variant in "${variants[@]}"; do
  for seed in $(seeds_of "$variant"); do dives+=("$variant:$seed"); done
done
echo "== simulate ${#dives[@]} dives (moderate seeds ${seeds[*]}; other waters ${other_seeds[*]}) and replay each as"
echo "   dead reckoning and the paper's runs, $jobs jobs at a time (a dive's replays start once it is simulated)"
specs=()
declare -A sim_of=()
for d in "${dives[@]}"; do
  variant="${d%%:*}" seed="${d#*:}" tag="$(prefix_of "${d%%:*}")-s${d#*:}"
  # DIVE_REUSE=1: a recording already in out/ (e.g. kept by DIVE_KEEP=1) is replayed, not simulated again.
  if [[ "${DIVE_REUSE:-0}" == 1 && -s "out/$tag.mcap" ]]; then sim_of[$tag]=""; continue; fi
  sim_of[$tag]="sim-$tag"
  specs+=("sim-$tag||build/bin/deepnav-sim --scenario tools/sim/scenarios/$(prefix_of "$variant").yaml \
--board board/sim-sea/board.yaml --seed $seed --no-truth-maps --out out/$tag.mcap")
done
for d in "${dives[@]}"; do
  variant="${d%%:*}" tag="$(prefix_of "${d%%:*}")-s${d#*:}"
  for run in $(runs_for "$variant"); do
    extra=""
    [[ "$run" == tl2 ]] && extra="--workspace-out out/$tag/tl2/workspace"
    # The board as it is now (the recording stores the one it was simulated with).
    specs+=("$tag-$run|${sim_of[$tag]}|build/bin/deepnav replay out/$tag.mcap --board board/sim-sea/board.yaml \
--out out/$tag/$run ${run_args[$run]} $extra")
  done
done
run_pool "${specs[@]}"
for d in "${dives[@]}"; do
  tag="$(prefix_of "${d%%:*}")-s${d#*:}"
  if [[ "$tag" != "sea-trial-s${seeds[0]}" && "${DIVE_KEEP:-0}" == 0 ]]; then rm -f "out/$tag.mcap"; fi
done
echo
sed -n '2,20p' "out/sea-trial-s${seeds[0]}-tl2.log"

echo "== figures: a stereo pair of the sea trial, its disparity, cloud planes, the stage-1 octomap"
build/bin/deepnav-figures "out/sea-trial-s${seeds[0]}.mcap" --time-s 230 \
  --workspace "out/sea-trial-s${seeds[0]}/tl2/workspace" --out out/figures

echo "== tables"
# One set of tables per water (its runs over its seeds), then the modality table across the waters.
{
  for variant in "${variants[@]}"; do
    prefix="$(prefix_of "$variant")"
    echo "### Sea trial, $variant water (seeds $(seeds_of "$variant"))"
    echo
    args=()
    for run in $(runs_for "$variant"); do args+=(--run "$run=out/$prefix-s*/$run"); done
    /usr/bin/python3 tools/eval/paper_tables.py "${args[@]}" --json "out/tables-$variant.json"
  done
  echo "### Modality against turbidity (EKF-adaptive)"
  echo
  args=()
  for variant in "${variants[@]}"; do args+=(--run "modality_$variant=out/$(prefix_of "$variant")-s*/tl2"); done
  /usr/bin/python3 tools/eval/paper_tables.py "${args[@]}" --json out/tables-modality.json
} | tee out/tables.md

echo "== report"
# Debian's interpreter: it has python3-matplotlib (a pyenv python3 earlier on PATH may not).
s1="out/sea-trial-s${seeds[0]}"
/usr/bin/python3 tools/eval/report.py --run "$s1/tl2" --compare "dr=$s1/dr" --compare "tl1=$s1/tl1" \
  --compare "all=$s1/all" --compare "tl3=$s1/tl3" --tables out/tables.md --figures out/figures --out report
echo "report written to report/index.html ($((SECONDS - start_s)) s after the build); disk: $(du -sh out | cut -f1)"
