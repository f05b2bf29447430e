#!/usr/bin/env bash
# The main job: build deepnav, simulate the default dive, replay it through the navigation loop, print
# the accuracy table and write the report (report/index.html).
#   tools/dive.sh [SCENARIO.yaml] [SEED]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scenario="${1:-tools/sim/scenarios/default.yaml}"
seed="${2:-1}"
name="$(basename "$scenario" .yaml)"

echo "== build"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=toolchains/native.cmake >/dev/null
cmake --build build -j"$(nproc)" --target deepnav deepnav-sim

mkdir -p out report
echo "== simulate: $scenario (seed $seed)"
build/bin/deepnav-sim --scenario "$scenario" --seed "$seed" --out "out/$name.mcap"
echo "== replay through the navigation loop"
build/bin/deepnav replay "out/$name.mcap" --out "out/$name"
echo "== report"
# Debian's interpreter: it has python3-matplotlib (a pyenv python3 earlier on PATH may not).
/usr/bin/python3 tools/eval/report.py --run "out/$name" --out report
echo "report written to report/index.html"
