#!/usr/bin/python3
"""One benchmark table: per-stage time per 688x516 stereo pair beside the DexROV paper's figures, the
EKF's costs, replay speed against real time and peak resident memory.

  tools/bench/bench_table.py [--build build] [--recording out-default/default.mcap]
                             [--sea-recording DIVE.mcap | --sea-duration S] [--set KEY=VALUE ...]
                             [--out bench.md]

Runs the Google Benchmark binaries of build/bin (CPU time, one thread), then `deepnav replay` of a
recording (default: a 30 s simulated dive it writes with deepnav-sim) for the speed against real time and
the peak resident memory of the whole replay (vision worker included). Then the vision worker's time per
stereo pair, per part, from the frames.csv of that replay and of a murky sea-trial dive
(tools/sim/scenarios/sea-trial-murky.yaml simulated with board/sim-sea/board.yaml, seed 3, replayed with
that board; default: the whole 300 s dive): mean, median, p95, p99 and max per part, against the targets
of issue 20 (mean <= 20 ms, p99 <= 50 ms per pair). --set passes board overrides to both replays (e.g.
vision.markers_coarse_search=true). Prints Markdown; docs/benchmarks.md shows the latest table with the
machine it ran on. The simulated dives and replays live in a temporary directory removed at the end."""
import argparse
import csv
import json
import os
import math
import platform
import re
import statistics
import resource
import subprocess
import shutil
import tempfile

# (binary, benchmark name, row label, target, paper figure)
ROWS = [
    ("bench_orbvo", "BM_OrbVoFrame/min_time:3.000", "VO-ORB, one stereo pair", "<= 8 ms", "0.145 s"),
    ("bench_planes", "BM_Chain", "VO-planes chain (ELAS 64 disp, cloud, filter, planes, registration)",
     "<= 150 ms", "3.151 s"),
    # ELAS rows, 6th field: libelas (its published source, one core) on the same input, measured by the
    # twelfth session (issue 20) on the VM of that day: (peer name, seconds); the row shows the ratio ours /
    # peer, with the peer's time scaled to this machine by SPEED_REFERENCE.
    ("bench_stereo", "BM_ElasDiveRobotics", "ELAS robotics, rendered dive pair, 64 disparities", "<= 0.5x libelas",
     "", ("libelas ROBOTICS", 43e-3)),
    ("bench_stereo", "BM_ElasDiveDense", "ELAS dense, rendered dive pair, 64 disparities", "<= 0.5x libelas", "",
     ("libelas ROBOTICS", 43e-3)),
    ("bench_stereo", "BM_ElasTsukubaDense", "ELAS dense, Middlebury tsukuba", "", "", ("libelas", 22.1e-3)),
    ("bench_stereo", "BM_Sgbm/wls:0", "SGBM (3-way)", "", ""),
    # CAPE (Proenca & Gao, IROS 2018): about 3.3 ms per 640x480 cloud on one core, from the paper (ours: 688x516,
    # 1.16x the pixels).
    ("bench_planes", "BM_PlaneExtractionTiles/step:1", "plane extraction, 688x516 cloud (tile grower, the default)",
     "<= 5 ms", "", ("CAPE 640x480 (paper)", 3.3e-3)),
    ("bench_planes", "BM_PlaneExtractionTiles/step:2", "plane extraction, 2-px grid (the chain's)", "", ""),
    ("bench_planes", "BM_PlaneExtractionPixels/step:1", "plane extraction, pixel grower (planes_growing=pixels)",
     "", "", ("CAPE 640x480 (paper)", 3.3e-3)),
    ("bench_planes", "BM_PlaneExtractionPixels/step:2", "plane extraction, pixel grower, 2-px grid", "", ""),
    ("bench_planes", "BM_PlaneRegistration", "plane registration", "", ""),
    ("bench_iqa", "BM_MdmGrey688x516", "MDM, grey", "<= 3 ms", ""),
    ("bench_markers", "BM_MarkersDetectAndPoseGrey688x516OneThread", "marker detection + pose", "", ""),
    ("bench_render", "BM_RenderDwellGrey", "simulator: render one pair (dwell)", "<= 50 ms", ""),
    ("bench_render", "BM_RenderSeabedGrey", "simulator: render one pair (seabed-filled)", "<= 50 ms", ""),
    ("bench_ekf", "BM_ImuPropagation/0", "EKF IMU propagation", "<= 5 us", ""),
    ("bench_ekf", "BM_ImuPropagation/4", "EKF IMU propagation, 4 clones", "<= 5 us", ""),
    ("bench_ekf", "BM_UpdateDvl/0", "EKF DVL update", "<= 20 us", ""),
    ("bench_ekf", "BM_UpdatePose/0", "EKF marker pose update", "<= 20 us", ""),
    ("bench_ekf", "BM_UpdateRelativePose/1", "EKF VO relative pose update", "<= 20 us", ""),
    ("bench_ekf", "BM_DelayedUpdateReplay50Imu/0", "EKF late update re-running 50 IMU steps", "", ""),
]


# Rows whose code has not changed since the twelfth session (OpenCV's SGBM, MDM, the renderer, the EKF
# propagation), with that session's figures (docs/benchmarks.md at 1194ae6, the VM on which libelas was
# measured): the median of their time there over their time here scales the peer figures measured there.
SPEED_REFERENCE = {
    ("bench_stereo", "BM_Sgbm/wls:0"): 68.3e-3,
    ("bench_iqa", "BM_MdmGrey688x516"): 70.14e-6,
    ("bench_render", "BM_RenderSeabedGrey"): 64.1e-3,
    ("bench_ekf", "BM_ImuPropagation/0"): 4.21e-6,
}


def speed_factor(results):
    """How many times faster than the twelfth session's VM this machine runs the reference rows (None
    when none ran)."""
    ratios = [ref / results[key] for key, ref in SPEED_REFERENCE.items() if results.get(key)]
    return statistics.median(ratios) if ratios else None


def peer_text(peer, t, factor):
    name, seconds = peer
    if not t:
        return f"{name} {human(seconds)}"
    if not factor:
        return f"{name} {human(seconds)} (other machine): ours {t / seconds:.2f}x its time"
    scaled = seconds / factor
    return (f"{name} {human(seconds)} on the twelfth session's VM, {human(scaled)} scaled to this one: "
            f"ours {t / scaled:.2f}x its time")


def run_benchmarks(bin_dir):
    by_binary = {}
    for binary, name, *_ in ROWS:
        by_binary.setdefault(binary, []).append(name)
    results = {}
    for binary, names in by_binary.items():
        path = os.path.join(bin_dir, binary)
        if not os.path.exists(path):
            continue
        pattern = "^(" + "|".join(n.replace("/", "/").replace(".", "\\.") for n in names) + ")$"
        out = subprocess.run([path, f"--benchmark_filter={pattern}", "--benchmark_format=json"],
                             capture_output=True, text=True, check=False)
        try:
            data = json.loads(out.stdout)
        except json.JSONDecodeError:
            continue
        for b in data.get("benchmarks", []):
            unit = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
            results[(binary, b["name"])] = b["cpu_time"] * unit
    return results


def human(seconds):
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.1f} ms"
    return f"{seconds * 1e6:.2f} us"


def overrides(sets):
    """deepnav replay's --set arguments."""
    return [arg for kv in sets for arg in ("--set", kv)]


def replay_figures(bin_dir, recording, work, sets):
    """(dive_s, wall_s, peak MiB, replay output directory) of the replay of the default dive."""
    os.makedirs(work, exist_ok=True)
    if not recording:
        recording = os.path.join(work, "dive.mcap")
        scenario = os.path.join(work, "short.yaml")
        with open("tools/sim/scenarios/default.yaml") as f:
            text = f.read().replace("duration_s: 120.0", "duration_s: 30.0")
        with open(scenario, "w") as f:
            f.write(text)
        subprocess.run([os.path.join(bin_dir, "deepnav-sim"), "--scenario", scenario, "--out", recording],
                       check=True, capture_output=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    subprocess.run([os.path.join(bin_dir, "deepnav"), "replay", recording, "--out", os.path.join(work, "replay")]
                   + overrides(sets), check=True, capture_output=True)
    peak_kib = max(before, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
    with open(os.path.join(work, "replay", "summary.json")) as f:
        s = json.load(f)
    return s["dive_s"], s["wall_s"], peak_kib / 1024.0, os.path.join(work, "replay")


def sea_replay(bin_dir, recording, duration_s, work, sets):
    """Replays the murky sea-trial dive (simulating it first when no recording is given); returns the
    replay's output directory."""
    os.makedirs(work, exist_ok=True)
    board = "board/sim-sea/board.yaml"
    if not recording:
        recording = os.path.join(work, "sea.mcap")
        scenario = "tools/sim/scenarios/sea-trial-murky.yaml"
        if duration_s:
            with open(scenario) as f:
                text = f.read()
            scenario = os.path.join(work, "sea-trial-murky.yaml")
            with open(scenario, "w") as f:
                f.write(re.sub(r"(?m)^duration_s: .*$", f"duration_s: {duration_s}", text))
        subprocess.run([os.path.join(bin_dir, "deepnav-sim"), "--scenario", scenario, "--board", board,
                        "--seed", "3", "--no-truth-maps", "--out", recording], check=True, capture_output=True)
    out = os.path.join(work, "replay")
    subprocess.run([os.path.join(bin_dir, "deepnav"), "replay", recording, "--board", board, "--out", out]
                   + overrides(sets), check=True, capture_output=True)
    return out


# frames.csv columns of the worker time per part (us); "rest" is total_us minus the three: rectification,
# MDM, markers and the pipeline's glue, which run on every pair.
PARTS = [("orb_us", "ORB VO"), ("planes_us", "dense stereo + plane VO (stage 2)"),
         ("map_us", "dense stereo + map insertion (stage 1)"), ("rest", "rectification, MDM, markers, glue"),
         ("total_us", "whole pair")]


def percentile(sorted_values, q):
    """Nearest-rank percentile (q in [0, 100]) of an ascending list."""
    rank = max(1, math.ceil(q / 100.0 * len(sorted_values)))
    return sorted_values[rank - 1]


def worker_times(frames_csv):
    """Per part: (pairs where it ran, mean, median, p95, p99, max) in seconds, from a replay's frames.csv."""
    per_part = {key: [] for key, _ in PARTS}
    with open(frames_csv) as f:
        for row in csv.DictReader(f):
            us = {k: int(row[k]) for k in ("orb_us", "planes_us", "map_us", "total_us")}
            us["rest"] = max(0, us["total_us"] - us["orb_us"] - us["planes_us"] - us["map_us"])
            for key, _ in PARTS:
                if us[key] > 0 or key in ("rest", "total_us"):
                    per_part[key].append(us[key] * 1e-6)
    stats = {}
    for key, values in per_part.items():
        if values:
            v = sorted(values)
            stats[key] = (len(v), statistics.fmean(v), statistics.median(v), percentile(v, 95), percentile(v, 99),
                          v[-1])
    return stats


def worker_rows(dive, stats):
    rows = []
    for key, label in PARTS:
        if key not in stats:
            rows.append(f"| {dive} | {label} | 0 | | | | | |")
            continue
        n, mean, median, p95, p99, peak = stats[key]
        rows.append(f"| {dive} | {label} | {n} | {human(mean)} | {human(median)} | {human(p95)} | {human(p99)} | "
                    f"{human(peak)} |")
    return rows


def verdict(dive, stats):
    n, mean, _, _, p99, _ = stats["total_us"]
    ok = "met" if mean <= 20e-3 and p99 <= 50e-3 else "not met"
    return (f"{dive}, whole pair: mean {human(mean)} (target <= 20 ms), p99 {human(p99)} (<= 50 ms) over {n} pairs: "
            f"{ok}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--recording", help="recording to replay (default: a 30 s simulated dive)")
    ap.add_argument("--sea-recording", help="murky sea-trial recording to replay (default: simulate one)")
    ap.add_argument("--sea-duration", type=float, help="simulate only this many seconds of the sea-trial dive")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="board override for both replays (repeatable)")
    ap.add_argument("--out", help="also write the Markdown here")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="deepnav_bench_")
    try:
        write_table(args, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def write_table(args, work):
    bin_dir = os.path.join(args.build, "bin")
    results = run_benchmarks(bin_dir)
    lines = [f"Machine: {platform.machine()}, {os.cpu_count()} cores, {platform.platform()}", "",
             "| stage | CPU time | target | paper or peer |", "|---|---|---|---|"]
    factor = speed_factor(results)
    for binary, name, label, target, paper, *peer in ROWS:
        t = results.get((binary, name))
        if peer and peer[0][0].startswith("libelas"):
            paper = peer_text(peer[0], t, factor)
        elif peer:
            paper = f"{peer[0][0]} {human(peer[0][1])}" + (f": ours {t / peer[0][1]:.2f}x its time" if t else "")
        lines.append(f"| {label} | {human(t) if t is not None else 'not run'} | {target} | {paper} |")
    if factor:
        lines += ["", f"This machine runs the unchanged reference rows (SGBM, MDM, seabed render, EKF propagation) "
                      f"{factor:.2f}x as fast as the twelfth session's VM (median of their ratios)."]
    if args.set:
        lines += ["", "Replays with " + ", ".join(f"`{kv}`" for kv in args.set) + "."]
    dive_s, wall_s, peak_mib, default_out = replay_figures(bin_dir, args.recording, os.path.join(work, "default"),
                                                           args.set)
    lines += ["", "| replay (full two-stage pipeline) | value |", "|---|---|",
              f"| dive replayed | {dive_s:.1f} s in {wall_s:.1f} s wall ({dive_s / wall_s:.2f}x real time) |",
              f"| peak resident memory of the replay | {peak_mib:.0f} MiB |"]
    sea_out = sea_replay(bin_dir, args.sea_recording, args.sea_duration, os.path.join(work, "sea"), args.set)
    dives = [("default dive", worker_times(os.path.join(default_out, "frames.csv"))),
             ("murky sea trial", worker_times(os.path.join(sea_out, "frames.csv")))]
    lines += ["", "| vision worker, per stereo pair | part | pairs | mean | median | p95 | p99 | max |",
              "|---|---|---|---|---|---|---|---|"]
    for dive, stats in dives:
        lines += worker_rows(dive, stats)
    lines += [""] + [f"- {verdict(dive, stats)}" for dive, stats in dives if "total_us" in stats]
    text = "\n".join(lines)
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
