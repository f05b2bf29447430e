#!/usr/bin/python3
"""One benchmark table: per-stage time per 688x516 stereo pair beside the DexROV paper's figures, the
EKF's costs, replay speed against real time and peak resident memory.

  tools/bench/bench_table.py [--build build] [--recording out-default/default.mcap] [--out bench.md]

Runs the Google Benchmark binaries of build/bin (CPU time, one thread), then `deepnav replay` of a
recording (default: a 30 s simulated dive it writes with deepnav-sim) for the speed against real time and
the peak resident memory of the whole replay (vision worker included). Prints Markdown; docs/benchmarks.md
shows the latest table with the machine it ran on."""
import argparse
import json
import os
import platform
import resource
import subprocess
import tempfile

# (binary, benchmark name, row label, target, paper figure)
ROWS = [
    ("bench_orbvo", "BM_OrbVoFrame/min_time:3.000", "VO-ORB, one stereo pair", "<= 30 ms", "0.145 s"),
    ("bench_planes", "BM_Chain", "VO-planes chain (ELAS 64 disp, cloud, filter, planes, registration)",
     "<= 150 ms", "3.151 s"),
    # ELAS rows, 6th field: libelas (its published source, one core) on the same input, measured on this
    # machine by an earlier session (issue 20): (peer name, seconds); the row shows the ratio ours / peer.
    ("bench_stereo", "BM_ElasDiveRobotics", "ELAS robotics, rendered dive pair, 64 disparities", "<= 21.5 ms",
     "", ("libelas ROBOTICS", 43e-3)),
    ("bench_stereo", "BM_ElasDiveDense", "ELAS dense, rendered dive pair, 64 disparities", "<= 21.5 ms", "",
     ("libelas ROBOTICS", 43e-3)),
    ("bench_stereo", "BM_ElasTsukubaDense", "ELAS dense, Middlebury tsukuba", "", "", ("libelas", 22.1e-3)),
    ("bench_stereo", "BM_Sgbm/wls:0", "SGBM (3-way)", "", ""),
    # CAPE (Proenca & Gao, IROS 2018): about 3.3 ms per 640x480 cloud on one core, from the paper (ours: 688x516,
    # 1.16x the pixels).
    ("bench_planes", "BM_PlaneExtraction/step:1", "plane extraction, 688x516 cloud", "<= 5 ms", "",
     ("CAPE 640x480 (paper)", 3.3e-3)),
    ("bench_planes", "BM_PlaneExtraction/step:2", "plane extraction, 2-px grid (the chain's)", "", ""),
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


def replay_figures(bin_dir, recording):
    work = tempfile.mkdtemp(prefix="deepnav_bench_")
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
    subprocess.run([os.path.join(bin_dir, "deepnav"), "replay", recording, "--out", os.path.join(work, "replay")],
                   check=True, capture_output=True)
    peak_kib = max(before, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
    with open(os.path.join(work, "replay", "summary.json")) as f:
        s = json.load(f)
    return s["dive_s"], s["wall_s"], peak_kib / 1024.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--recording", help="recording to replay (default: a 30 s simulated dive)")
    ap.add_argument("--out", help="also write the Markdown here")
    args = ap.parse_args()
    bin_dir = os.path.join(args.build, "bin")
    results = run_benchmarks(bin_dir)
    lines = [f"Machine: {platform.machine()}, {os.cpu_count()} cores, {platform.platform()}", "",
             "| stage | CPU time | target | paper or peer |", "|---|---|---|---|"]
    for binary, name, label, target, paper, *peer in ROWS:
        t = results.get((binary, name))
        if peer:
            paper = f"{peer[0][0]} {human(peer[0][1])}" + (f": ours {t / peer[0][1]:.2f}x its time" if t else "")
        lines.append(f"| {label} | {human(t) if t is not None else 'not run'} | {target} | {paper} |")
    dive_s, wall_s, peak_mib = replay_figures(bin_dir, args.recording)
    lines += ["", "| replay (full two-stage pipeline) | value |", "|---|---|",
              f"| dive replayed | {dive_s:.1f} s in {wall_s:.1f} s wall ({dive_s / wall_s:.2f}x real time) |",
              f"| peak resident memory of the replay | {peak_mib:.0f} MiB |"]
    text = "\n".join(lines)
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
