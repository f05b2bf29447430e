#!/usr/bin/env bash
# Builds the parser fuzz harnesses (clang, libFuzzer, ASan + UBSan) in their own build directory and
# runs each one for a fixed time on a seed corpus made from ../shared/data (when present) and from
# small well-formed frames. Exit 0: no crash, leak, out-of-bounds access or undefined behaviour;
# 1: a harness failed (its reproducer is left in the build directory); 77: clang/libFuzzer missing.
#
#   tools/fuzz/run_fuzzers.sh [--build-dir DIR] [--seconds N] [--only NAME]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$root/build-fuzz"
seconds=10
only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    *) echo "usage: $0 [--build-dir DIR] [--seconds N] [--only NAME]" >&2; exit 2 ;;
  esac
done

clang=""
for c in clang++-14 clang++-15 clang++; do
  if command -v "$c" >/dev/null 2>&1; then clang="$c"; break; fi
done
if [ -z "$clang" ]; then
  echo "run_fuzzers: no clang++ found (tools/setup.sh installs clang-14); skipping" >&2
  exit 77
fi

cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$clang" >/dev/null
cmake --build "$build" -j"$(nproc)" >/dev/null

# Seed corpora: real captures cut into pieces, plus one well-formed frame of each format.
shared="${DEEPNAV_SHARED_DATA:-$root/../shared/data}"
seeds="$build/seeds"
rm -rf "$seeds"
mkdir -p "$seeds"/{pd0,nmea0183,pd6,wl_a50,xsens,n2k,can_mapping,sensor_stream}
if [ -d "$shared/dvl" ]; then
  for f in "$shared"/dvl/*.PD0; do head -c 4096 "$f" > "$seeds/pd0/$(basename "$f")"; done
fi
if [ -d "$shared/nmea" ]; then
  for f in "$shared"/nmea/*.log; do head -c 2048 "$f" > "$seeds/nmea0183/$(basename "$f")"; done
fi
if [ -d "$shared/can" ]; then head -c 4096 "$shared/can/candumpSample2.txt" > "$seeds/n2k/candump"; fi
printf '$HEHDT,274.07,T*03\r\n$HCHDG,101.1,2.0,W,3.5,E*3C\r\n$HEROT,-3.4,A*01\r\n' > "$seeds/nmea0183/heading"
printf ':SA, -2.31, +1.12,123.45\n:TS,21051012345612,35.0,+12.5,  12.0,1500.0,  0\n:BI,  +100,  -500,   +20,     5,A\n:BD,     +12.30,     -4.50,      0.20,  8.25,  0.10\n' > "$seeds/pd6/ensemble"
printf 'wrz,0.120,-0.400,2.000,y,1.30,1.855,1e-07;0;1.4;0;1.2;0;0.2;0;1e+09,1664894633045000,1664894633085000,14.1,0*4d' > "$seeds/wl_a50/wrz"
printf '{"vx": 0.1, "vy": 0.2, "vz": 0.0, "fom": 0.002, "altitude": 1.5, "covariance": [[1,0,0],[0,1,0],[0,0,1]], "transducers": [{"id": 0, "velocity": 0.1, "distance": 1.6, "rssi": -30, "nsd": -90, "beam_valid": true}], "velocity_valid": true, "status": 0, "type": "velocity"}' > "$seeds/wl_a50/json"
printf '\xfa\xff\x36\x0f\x10\x20\x02\x00\x01\x40\x20\x0c\x00\x00\x00\x00\x00\x00\x00\x00\x41\x1c\xf5\xc3\x00' > "$seeds/xsens/mtdata2"
printf '0x100:0:i16le:0.001:gyro_x;0x101:2:f32be:1:heading\n\x00\x00\x01\x00\x08\x01\x02\x03\x04\x05\x06\x07\x08' > "$seeds/can_mapping/spec"
printf '\x03$HEHDT,4.0,T*2B\r\n' > "$seeds/sensor_stream/nmea"
cp "$seeds/pd0/"* "$seeds/sensor_stream/" 2>/dev/null || true

status=0
for bin in "$build"/fuzz_*; do
  [ -x "$bin" ] || continue
  name="$(basename "$bin")"
  [ -n "$only" ] && [ "$name" != "fuzz_$only" ] && continue
  corpus="$build/corpus/${name#fuzz_}"
  mkdir -p "$corpus"
  log="$build/$name.log"
  if (cd "$build" && "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
        -print_final_stats=1 "$corpus" "$seeds/${name#fuzz_}" >"$log" 2>&1); then
    echo "run_fuzzers: $name: $(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{print $2}') runs in ${seconds}s, no failure"
  else
    echo "run_fuzzers: $name FAILED (see $log and the crash-* reproducer in $build)" >&2
    tail -n 30 "$log" >&2
    status=1
  fi
done
exit $status
