#!/usr/bin/python3
"""The DexROV paper's tables from replay output directories (summary.json + frames.csv of each run),
each figure the mean ± standard deviation over the runs given for that name (one run per seed).

  Table III(a): computation per VO mode (time per stereo pair and CPU share of one core at the camera rate)
  Table III(b): EKF-all (every VO on every pair) against EKF-adaptive
  Table V:      T_L1 (navigation sensors + markers), T_L2 (T_L1 + adaptive VO), T_L3 (T_L2 without markers
                in stage 2)
  Modality:     how the adaptive choice shifts with turbidity (clear / default / murky)
  Consistency and drift: aligned ATE, RPE per metre travelled, NEES in the 95 % band, per run
  Modalities:   results offered to the filter, fused, rejected by its gate, otherwise dropped, per run
The dead-reckoning run (name dr: navigation sensors only, `--set vision.vo_mode=none --set
markers.enabled=false`) is a row of every accuracy table.

Usage: paper_tables.py --run NAME=DIR ... [--json OUT.json]; NAME may repeat (one DIR per seed) and DIR
may be a glob (quoted: --run 'tl2=out/seed*/tl2'). Names: dr, tl1, tl2, tl3, all, and modality_<scenario>
for the turbidity runs. Prints Markdown; absent figures (no panel estimate, no truth) print as n/a."""
import argparse
import csv
import glob
import json
import math
import os

RUN_TITLES = {"dr": "dead reckoning (nav sensors only)", "tl1": "T_L1 nav sensors + markers",
              "tl2": "T_L2 = EKF-adaptive (T_L1 + adaptive VO)", "tl3": "T_L3 T_L2 without markers in stage 2",
              "all": "EKF-all"}
MODALITIES = ("dvl", "compass", "depth", "markers", "vo_orb", "vo_planes")


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
    """Mean and sample standard deviation (n - 1; 0 for one value); NaN for none."""
    if not values:
        return float("nan"), float("nan")
    m = sum(values) / len(values)
    if len(values) < 2:
        return m, 0.0
    return m, math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1))


def get(d, *path):
    """d[path[0]][path[1]]...; None when any level is missing or null."""
    for key in path:
        if not isinstance(d, dict) or d.get(key) is None:
            return None
        d = d[key]
    return d


def run_metrics(summary):
    """The scalar figures of one run; None where the run has none (e.g. no panel estimate)."""
    m = {
        "odom_pos_m": get(summary, "position_error_m", "mean"),
        "odom_ori_deg": get(summary, "orientation_error_deg", "mean"),
        "odom_pos_stage2_m": get(summary, "odom_error", "stage2", "position_m", "mean"),
        "odom_ori_stage2_deg": get(summary, "odom_error", "stage2", "orientation_deg", "mean"),
        "panel_pos_window_m": get(summary, "panel_error", "stage2_first_60s", "position_m", "mean"),
        "panel_ori_window_deg": get(summary, "panel_error", "stage2_first_60s", "orientation_deg", "mean"),
        "panel_pos_m": get(summary, "panel_error", "whole", "position_m", "mean"),
        "panel_ori_deg": get(summary, "panel_error", "whole", "orientation_deg", "mean"),
        "panel_pos_stage2_m": get(summary, "panel_error", "stage2", "position_m", "mean"),
        "panel_ori_stage2_deg": get(summary, "panel_error", "stage2", "orientation_deg", "mean"),
        "ate_pos_m": get(summary, "ate", "position_rmse_m"),
        "ate_rot_deg": get(summary, "ate", "rotation_rmse_deg"),
        "rpe_percent": get(summary, "rpe", "translation_percent", "mean"),
        "rpe_deg_per_m": get(summary, "rpe", "rotation_deg_per_m", "mean"),
        "nees_pos_in_band": get(summary, "nees", "position", "in_band_fraction"),
        "nees_pos_mean": get(summary, "nees", "position", "mean"),
        "nees_heading_in_band": get(summary, "nees", "heading", "in_band_fraction"),
        "nees_heading_mean": get(summary, "nees", "heading", "mean"),
        "m_a": summary.get("smoothness_m_a"),
        "vo_fused": get(summary, "vo", "accepted"),
        "vo_orb": get(summary, "vo", "accepted_orb"),
        "vo_planes": get(summary, "vo", "accepted_planes"),
        "markers_fused": get(summary, "markers", "poses_accepted"),
        "stage2_at_s": summary.get("stage2_at_s") if summary.get("stage2_at_s", -1) >= 0 else None,
        "vision_cpu_percent": vision_cpu_percent(summary),
    }
    if get(summary, "rpe", "pairs") == 0:
        m["rpe_percent"] = m["rpe_deg_per_m"] = None
    for name in MODALITIES:
        for field in ("offered", "fused", "rejected_gate", "rejected_other"):
            m[f"mod_{name}_{field}"] = get(summary, "modalities", name, field)
    return m


def vision_cpu_percent(summary):
    """The vision worker's busy time over the dive, in % of one core (loop task "vision": runs x mean)."""
    dive_s = summary.get("dive_s")
    for task in get(summary, "loop", "tasks") or []:
        if task.get("name") == "vision" and dive_s:
            return 100.0 * task["runs"] * task["mean_us"] / 1e6 / dive_s
    return None


def aggregate(per_run):
    """{key: {"mean", "std", "n"}} over the runs that have the figure (n = 0: none has it)."""
    out = {}
    for key in per_run[0]:
        values = [r[key] for r in per_run if r[key] is not None]
        m, s = mean_std(values)
        out[key] = {"mean": m if values else None, "std": s if values else None, "n": len(values)}
    return out


def accuracy_row(name, runs):
    row = aggregate([run_metrics(s) for s, _ in runs])
    row["name"] = RUN_TITLES.get(name, name)
    row["seeds"] = len(runs)
    return row


def timing_rows(frames, camera_rate_hz=10.0):
    """Table III(a): worker time per stereo pair in stage 2, by the part that ran (pairs of all seeds)."""
    stage2 = [f for f in frames if int(f["stage"]) == 2]
    rows = []
    for label, key, pick in (("VO-ORB (tracking + pose)", "orb_us", lambda f: f["orb_us"] > 0),
                             ("VO-planes (dense stereo, filter, planes, registration)", "planes_us",
                              lambda f: f["planes_us"] > 0),
                             ("whole pair, adaptive (MDM, markers, selected VO)", "total_us", lambda f: True)):
        values = [f[key] / 1e6 for f in stage2 if pick(f)]
        m, s = mean_std(values)
        rows.append({"mode": label, "pairs": len(values), "time_s": m if values else None,
                     "time_std_s": s if values else None,
                     "cpu_percent": 100.0 * m * camera_rate_hz if values else None})
    return rows


def modality_row(name, runs):
    per_run = []
    for summary, frames in runs:
        stage2 = [f for f in frames if int(f["stage"]) == 2]
        q = [f["image_quality"] for f in frames if f["image_quality"] >= 0]
        planes = sum(1 for f in stage2 if int(f["selected"]) == 2)
        m = run_metrics(summary)
        per_run.append({"pairs_stage2": len(stage2) if frames else None,
                        "mean_quality": mean_std(q)[0] if q else None,
                        "planes_share": planes / len(stage2) if stage2 else None,
                        "vo_orb": m["vo_orb"], "vo_planes": m["vo_planes"], "odom_pos_m": m["odom_pos_m"],
                        "odom_ori_deg": m["odom_ori_deg"], "panel_pos_m": m["panel_pos_m"],
                        "panel_ori_deg": m["panel_ori_deg"]})
    row = aggregate(per_run)
    row["scenario"] = name
    row["seeds"] = len(runs)
    return row


def fmt(cell, digits, scale=1.0):
    """mean ± std over the seeds; n/a when no run has the figure."""
    if cell is None or cell["mean"] is None:
        return "n/a"
    m, s = cell["mean"] * scale, cell["std"] * scale
    return f"{m:.{digits}f}" if cell["n"] < 2 else f"{m:.{digits}f} ± {s:.{digits}f}"


def count(cell):
    """A count: its mean over the seeds, no spread."""
    return "n/a" if cell is None or cell["mean"] is None else f"{cell['mean']:.0f}"


def fmt_pair(a, b, digits_a, digits_b):
    return f"{fmt(a, digits_a)} / {fmt(b, digits_b)}"


def accuracy_lines(title, rows):
    out = [title, "",
           "| run | seeds | odom position (m) | odom orientation (deg) | panel-relative position (m) | "
           "panel-relative orientation (deg) | odom, stage 2 (m / deg) | panel-relative, stage 2 (m / deg) | "
           "panel-relative, first 60 s of stage 2 (m / deg) | m_A | VO fused (orb / planes) | "
           "marker poses fused | stage 2 from (s) | vision CPU (% of a core) |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['name']} | {r['seeds']} | {fmt(r['odom_pos_m'], 3)} | {fmt(r['odom_ori_deg'], 2)} | "
                   f"{fmt(r['panel_pos_m'], 3)} | {fmt(r['panel_ori_deg'], 2)} | "
                   f"{fmt_pair(r['odom_pos_stage2_m'], r['odom_ori_stage2_deg'], 3, 2)} | "
                   f"{fmt_pair(r['panel_pos_stage2_m'], r['panel_ori_stage2_deg'], 3, 2)} | "
                   f"{fmt_pair(r['panel_pos_window_m'], r['panel_ori_window_deg'], 3, 2)} | {fmt(r['m_a'], 3)} | "
                   f"{count(r['vo_fused'])} ({count(r['vo_orb'])} / {count(r['vo_planes'])}) | "
                   f"{count(r['markers_fused'])} | {fmt(r['stage2_at_s'], 1)} | "
                   f"{fmt(r['vision_cpu_percent'], 0)} |")
    return out + [""]


def drift_lines(rows):
    out = ["Consistency and drift (whole dive): ATE after SE(3) alignment (RMSE), RPE over 1 m of travel, "
           "NEES of the filter against its covariance (share of ticks inside the 95 % chi-square band; "
           "mean, expected 3 and 1)", "",
           "| run | seeds | ATE position (m) | ATE rotation (deg) | RPE (% of distance) | RPE (deg/m) | "
           "NEES position in band | NEES position mean | NEES heading in band | NEES heading mean |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['name']} | {r['seeds']} | {fmt(r['ate_pos_m'], 3)} | {fmt(r['ate_rot_deg'], 2)} | "
                   f"{fmt(r['rpe_percent'], 2)} | {fmt(r['rpe_deg_per_m'], 3)} | {fmt(r['nees_pos_in_band'], 2)} | "
                   f"{fmt(r['nees_pos_mean'], 1)} | {fmt(r['nees_heading_in_band'], 2)} | "
                   f"{fmt(r['nees_heading_mean'], 1)} |")
    return out + [""]


def modalities_lines(rows):
    out = ["Per modality: offered / fused / rejected by the gate / otherwise dropped (invalid, late, frozen, "
           "before alignment, VO without clone), mean over the seeds", "",
           "| run | " + " | ".join(MODALITIES) + " |", "|---|" + "---|" * len(MODALITIES)]
    for r in rows:
        cells = []
        for name in MODALITIES:
            cells.append(" / ".join(count(r[f"mod_{name}_{f}"])
                                    for f in ("offered", "fused", "rejected_gate", "rejected_other")))
        out.append(f"| {r['name']} | " + " | ".join(cells) + " |")
    return out + [""]


def markdown(tables):
    out = []
    if tables.get("timing"):
        out += ["Table III(a): computation per VO mode (stage 2, this machine, one worker thread; pairs of all "
                "seeds)", "",
                "| mode | pairs | time per pair (s) | CPU at 10 Hz (% of a core) | paper (s) |", "|---|---|---|---|---|"]
        paper = ["0.145", "3.151", "-"]
        for r, p in zip(tables["timing"], paper):
            if r["time_s"] is None:
                out.append(f"| {r['mode']} | 0 | n/a | n/a | {p} |")
                continue
            out.append(f"| {r['mode']} | {r['pairs']} | {r['time_s']:.4f} ± {r['time_std_s']:.4f} | "
                       f"{r['cpu_percent']:.0f} | {p} |")
        out.append("")
    for key, title in (("iii_b", "Table III(b): EKF-all against EKF-adaptive (mean error per run; ± over seeds)"),
                       ("v", "Table V: localisation tests (mean error per run; ± over seeds)")):
        if tables.get(key):
            out += accuracy_lines(title, tables[key])
    if tables.get("modality"):
        out += ["Modality choice against turbidity (EKF-adaptive; the dead-reckoning row: default water)", "",
                "| scenario | seeds | stage-2 pairs | mean m_I | share on planes | VO fused (orb / planes) | "
                "odom position (m) | odom orientation (deg) | panel-relative position (m) | "
                "panel-relative orientation (deg) |", "|---|---|---|---|---|---|---|---|---|---|"]
        for r in tables["modality"]:
            out.append(f"| {r['scenario']} | {r['seeds']} | {count(r['pairs_stage2'])} | {fmt(r['mean_quality'], 3)} | "
                       f"{fmt(r['planes_share'], 2)} | {count(r['vo_orb'])} / {count(r['vo_planes'])} | "
                       f"{fmt(r['odom_pos_m'], 3)} | {fmt(r['odom_ori_deg'], 2)} | {fmt(r['panel_pos_m'], 3)} | "
                       f"{fmt(r['panel_ori_deg'], 2)} |")
        out.append("")
    if tables.get("drift"):
        out += drift_lines(tables["drift"])
    if tables.get("modalities"):
        out += modalities_lines(tables["modalities"])
    return "\n".join(out)


def build(runs):
    """runs: {name: [dir, ...]} (one dir per seed)."""
    loaded = {name: [load(d) for d in dirs] for name, dirs in runs.items()}
    tables = {}
    if any(frames for _, frames in loaded.get("tl2", [])):
        tables["timing"] = timing_rows([f for _, frames in loaded["tl2"] for f in frames])
    dr = ["dr"] if "dr" in loaded else []
    tables["iii_b"] = [accuracy_row(k, loaded[k]) for k in dr + ["all", "tl2"] if k in loaded]
    tables["v"] = [accuracy_row(k, loaded[k]) for k in dr + ["tl1", "tl2", "tl3"] if k in loaded]
    modality = [modality_row(k[len("modality_"):], loaded[k]) for k in runs if k.startswith("modality_")]
    if modality and dr:
        modality.insert(0, modality_row("dead reckoning", loaded["dr"]))
    tables["modality"] = modality
    order = [k for k in ("dr", "tl1", "tl2", "tl3", "all") if k in loaded]
    tables["drift"] = [accuracy_row(k, loaded[k]) for k in order]
    tables["modalities"] = tables["drift"]
    return tables


def parse_runs(items, error):
    """["NAME=DIR or glob", ...] -> {NAME: [DIR, ...]} in the order given."""
    runs = {}
    for item in items:
        name, _, pattern = item.partition("=")
        dirs = sorted(d for d in glob.glob(pattern) if os.path.isdir(d)) if pattern else []
        if not name or not dirs:
            error(f"--run {item}: expected NAME=DIR (or a glob) naming existing directories")
        runs.setdefault(name, []).extend(d for d in dirs if d not in runs.get(name, []))
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", action="append", default=[], help="NAME=DIR (or glob) of a replay output; repeatable")
    ap.add_argument("--json", help="write the tables as JSON here")
    args = ap.parse_args()
    tables = build(parse_runs(args.run, ap.error))
    print(markdown(tables))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(tables, f, indent=1)


if __name__ == "__main__":
    main()
