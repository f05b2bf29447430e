#!/usr/bin/python3
"""The DexROV paper's tables from replay output directories (summary.json + frames.csv of each run).

  Table III(a): computation per VO mode (time per stereo pair and CPU share of one core at the camera rate)
  Table III(b): EKF-all (every VO on every pair) against EKF-adaptive
  Table V:      T_L1 (navigation sensors + markers), T_L2 (T_L1 + adaptive VO), T_L3 (T_L2 without markers
                in stage 2)
  Modality:     how the adaptive choice shifts with turbidity (clear / default / murky)

Usage: paper_tables.py --run NAME=DIR ... [--json OUT.json]; names used: tl1, tl2, tl3, all, and
modality_<scenario> for the turbidity runs. Prints Markdown."""
import argparse
import csv
import json
import math
import os


def load(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    frames = []
    path = os.path.join(run_dir, "frames.csv")
    if os.path.exists(path):
        with open(path) as f:
            frames = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    return summary, frames


def mean_std(values):
    if not values:
        return float("nan"), float("nan")
    m = sum(values) / len(values)
    return m, math.sqrt(sum((v - m) ** 2 for v in values) / len(values))


def accuracy_row(name, summary):
    p = summary.get("position_error_m", {})
    o = summary.get("orientation_error_deg", {})
    vo = summary.get("vo", {})
    return {"name": name, "pos_mean_m": p.get("mean", float("nan")), "pos_std_m": p.get("std", float("nan")),
            "ori_mean_deg": o.get("mean", float("nan")), "ori_std_deg": o.get("std", float("nan")),
            "m_a": summary.get("smoothness_m_a", float("nan")), "vo_fused": vo.get("accepted", 0),
            "vo_orb": vo.get("accepted_orb", 0), "vo_planes": vo.get("accepted_planes", 0),
            "markers_fused": summary.get("markers", {}).get("poses_accepted", 0),
            "stage2_at_s": summary.get("stage2_at_s", -1)}


def timing_rows(frames, camera_rate_hz=10.0):
    """Table III(a): worker time per stereo pair in stage 2, by the part that ran."""
    stage2 = [f for f in frames if int(f["stage"]) == 2]
    rows = []
    for label, key, pick in (("VO-ORB (tracking + pose)", "orb_us", lambda f: f["orb_us"] > 0),
                             ("VO-planes (dense stereo, filter, planes, registration)", "planes_us",
                              lambda f: f["planes_us"] > 0),
                             ("whole pair, adaptive (MDM, markers, selected VO)", "total_us", lambda f: True)):
        values = [f[key] / 1e6 for f in stage2 if pick(f)]
        m, s = mean_std(values)
        rows.append({"mode": label, "pairs": len(values), "time_s": m, "time_std_s": s,
                     "cpu_percent": 100.0 * m * camera_rate_hz if values else float("nan")})
    return rows


def modality_row(name, summary, frames):
    stage2 = [f for f in frames if int(f["stage"]) == 2]
    q = [f["image_quality"] for f in frames if f["image_quality"] >= 0]
    planes = sum(1 for f in stage2 if int(f["selected"]) == 2)
    return {"scenario": name, "pairs_stage2": len(stage2), "mean_quality": mean_std(q)[0],
            "planes_share": planes / len(stage2) if stage2 else float("nan"),
            "vo_orb": summary.get("vo", {}).get("accepted_orb", 0),
            "vo_planes": summary.get("vo", {}).get("accepted_planes", 0),
            "pos_mean_m": summary.get("position_error_m", {}).get("mean", float("nan")),
            "ori_mean_deg": summary.get("orientation_error_deg", {}).get("mean", float("nan"))}


def markdown(tables):
    out = []
    if tables.get("timing"):
        out += ["Table III(a): computation per VO mode (stage 2, this machine, one worker thread)", "",
                "| mode | pairs | time per pair (s) | CPU at 10 Hz (% of a core) | paper (s) |", "|---|---|---|---|---|"]
        paper = ["0.145", "3.151", "-"]
        for r, p in zip(tables["timing"], paper):
            out.append(f"| {r['mode']} | {r['pairs']} | {r['time_s']:.4f} ± {r['time_std_s']:.4f} | "
                       f"{r['cpu_percent']:.0f} | {p} |")
        out.append("")
    for key, title in (("iii_b", "Table III(b): EKF-all against EKF-adaptive"),
                       ("v", "Table V: localisation tests")):
        rows = tables.get(key, [])
        if not rows:
            continue
        out += [title, "", "| run | position error (m) | orientation error (deg) | m_A | VO fused (orb / planes) | "
                "marker poses fused | stage 2 from (s) |", "|---|---|---|---|---|---|---|"]
        for r in rows:
            out.append(f"| {r['name']} | {r['pos_mean_m']:.3f} ± {r['pos_std_m']:.3f} | "
                       f"{r['ori_mean_deg']:.2f} ± {r['ori_std_deg']:.2f} | {r['m_a']:.3f} | "
                       f"{r['vo_fused']} ({r['vo_orb']} / {r['vo_planes']}) | {r['markers_fused']} | "
                       f"{r['stage2_at_s']:.1f} |")
        out.append("")
    if tables.get("modality"):
        out += ["Modality choice against turbidity (EKF-adaptive)", "",
                "| scenario | stage-2 pairs | mean m_I | share on planes | VO fused (orb / planes) | "
                "position error (m) | orientation error (deg) |", "|---|---|---|---|---|---|---|"]
        for r in tables["modality"]:
            out.append(f"| {r['scenario']} | {r['pairs_stage2']} | {r['mean_quality']:.3f} | "
                       f"{r['planes_share']:.2f} | {r['vo_orb']} / {r['vo_planes']} | {r['pos_mean_m']:.3f} | "
                       f"{r['ori_mean_deg']:.2f} |")
        out.append("")
    return "\n".join(out)


def build(runs):
    loaded = {name: load(d) for name, d in runs.items()}
    tables = {}
    if "tl2" in loaded:
        tables["timing"] = timing_rows(loaded["tl2"][1])
    names = {"all": "EKF-all", "tl2": "EKF-adaptive"}
    tables["iii_b"] = [accuracy_row(names[k], loaded[k][0]) for k in ("all", "tl2") if k in loaded]
    names_v = {"tl1": "T_L1 nav sensors + markers", "tl2": "T_L2 T_L1 + adaptive VO",
               "tl3": "T_L3 T_L2 without markers in stage 2"}
    tables["v"] = [accuracy_row(names_v[k], loaded[k][0]) for k in ("tl1", "tl2", "tl3") if k in loaded]
    tables["modality"] = [modality_row(k[len("modality_"):], *loaded[k]) for k in runs if k.startswith("modality_")]
    return tables


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", action="append", default=[], help="NAME=DIR of a replay output")
    ap.add_argument("--json", help="write the tables as JSON here")
    args = ap.parse_args()
    runs = {}
    for item in args.run:
        name, _, path = item.partition("=")
        if not path or not os.path.isdir(path):
            ap.error(f"--run {item}: expected NAME=DIR with an existing directory")
        runs[name] = path
    tables = build(runs)
    print(markdown(tables))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(tables, f, indent=1)


if __name__ == "__main__":
    main()
