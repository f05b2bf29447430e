#!/usr/bin/python3
"""Dive report: reads replay output directories (summary.json, trajectory.tum, truth.tum, frames.csv)
and writes report/index.html with matplotlib figures in the style of the DexROV paper:
  Fig. 6  top view of the trajectory, each pose's position error as colour and circle size;
  Fig. 5  orientation error over time per VO setting, marker-less intervals and panel-side changes
          marked, and the image-quality curve m_I with the modality threshold under it;
  the error in the odometry frame beside the panel-relative one (T_panel_robot), and the NEES of
          position and heading per tick with the 95 % chi-square band (nees.csv);
  per source, the innovation test ratio and the normalised innovation of every fusion (fusion.csv);
  one stereo pair with its disparity, the filtered cloud with its planes, the stage-1 octomap;
  the paper's tables (from tools/eval/paper_tables.py)."""
import argparse
import csv
import html
import json
import math
import os
import shutil

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_tum(path):
    data = np.loadtxt(path, ndmin=2)
    return data[:, 0], data[:, 1:4], data[:, 4:8]


def interpolate(t_query, t, values):
    return np.stack([np.interp(t_query, t, values[:, i]) for i in range(values.shape[1])], axis=1)


def quat_angle_deg(q_est, q_true):
    dot = np.abs(np.sum(q_est * q_true, axis=1))
    return np.degrees(2.0 * np.arccos(np.clip(dot, -1.0, 1.0)))


def errors(run):
    t, p, q = read_tum(os.path.join(run, "trajectory.tum"))
    tt, pt, qt = read_tum(os.path.join(run, "truth.tum"))
    inside = (t >= tt[0]) & (t <= tt[-1])
    t, p, q = t[inside], p[inside], q[inside]
    p_true = interpolate(t, tt, pt)
    idx = np.clip(np.searchsorted(tt, t), 0, len(tt) - 1)
    return t, p, p_true, np.linalg.norm(p - p_true, axis=1), quat_angle_deg(q, qt[idx])


def read_frames(run):
    path = os.path.join(run, "frames.csv")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else None


def top_view(path, p, p_true, pos_err):
    fig, ax = plt.subplots(figsize=(7, 6))
    ax.plot(p_true[:, 0], p_true[:, 1], color="0.6", lw=1, label="ground truth")
    step = max(1, len(p) // 400)
    scale = 0.05 / max(pos_err.max(), 1e-6)
    sc = ax.scatter(p[::step, 0], p[::step, 1], c=pos_err[::step], s=8 + 400 * scale * pos_err[::step],
                    cmap="viridis", alpha=0.7, label="estimate (colour and size: position error)")
    fig.colorbar(sc, ax=ax, label="position error (m)")
    ax.set_xlabel("x in odom (m)")
    ax.set_ylabel("y in odom (m)")
    ax.set_aspect("equal")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), fontsize=8)
    ax.set_title("Fig. 6: top view, EKF-adaptive (T_L2)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def shade_intervals(ax, t, mask, colour, label):
    """Shades the time spans where mask holds."""
    first = True
    start = None
    for ti, m in zip(t, mask):
        if m and start is None:
            start = ti
        if not m and start is not None:
            ax.axvspan(start, ti, color=colour, alpha=0.15, lw=0, label=label if first else None)
            first, start = False, None
    if start is not None:
        ax.axvspan(start, t[-1], color=colour, alpha=0.15, lw=0, label=label if first else None)


def fig5(path, runs, frames, threshold, t0):
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    for name, run in runs.items():
        if not os.path.exists(os.path.join(run, "truth.tum")):
            continue
        t, _, _, _, ori_err = errors(run)
        a1.plot(t - t0, ori_err, lw=1, label=name)
    if frames is not None:
        tf = frames["t_s"] - t0
        shade_intervals(a1, tf, frames["markers"] == 0, "tab:red", "no marker in view")
        face = frames["face"]
        last = None
        for ti, fc in zip(tf, face):
            if fc >= 0 and last is not None and fc != last:
                a1.axvline(ti, color="k", ls=":", lw=0.8)
            if fc >= 0:
                last = fc
        stage2 = tf[frames["stage"] == 2]
        if len(stage2):
            a1.axvline(stage2[0], color="tab:green", lw=1.2, label="stage 2 begins")
        q = frames["image_quality"]
        a2.plot(tf, q, lw=1, color="tab:blue", label="image quality m_I")
        a2.axhline(threshold, color="tab:orange", ls="--", label=f"threshold {threshold}")
        planes = frames["selected"] == 2
        a2.scatter(tf[planes], q[planes], s=4, color="tab:purple", label="plane VO selected")
        a2.set_ylim(0, 1)
        a2.legend(fontsize=7, loc="lower left")
    a1.set_ylabel("orientation error (deg)")
    a1.legend(fontsize=7, loc="upper right")
    a1.set_title("Fig. 5: orientation error per setting; dotted lines: panel-side changes")
    a2.set_xlabel("dive time (s)")
    a2.set_ylabel("m_I")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def nees_plot(path, run, summary, t0):
    """NEES of position (3 dof) and heading (1 dof) per tick against the filter's covariance, with the 95 %
    chi-square band per tick and the band of the mean over the run."""
    data = np.loadtxt(os.path.join(run, "nees.csv"), delimiter=",", skiprows=1, ndmin=2)
    if data.size == 0:
        return False
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for ax, column, key, title in ((axes[0], 1, "position", "position NEES (3 dof)"),
                                   (axes[1], 2, "heading", "heading NEES (1 dof)")):
        n = summary.get("nees", {}).get(key, {})
        values = np.maximum(data[:, column], 1e-6)
        ax.semilogy(data[:, 0] - t0, values, lw=0.6, color="tab:blue", label="NEES per tick")
        if n.get("band"):
            lo, hi = n["band"]
            ax.axhspan(max(lo, 1e-6), hi, color="tab:green", alpha=0.15,
                       label=f"95 % band per tick [{lo:.3g}, {hi:.3g}]")
        if n.get("mean") is not None:
            lo, hi = n["mean_band"]
            ax.axhline(n["mean"], color="tab:red", lw=1,
                       label=f"mean {n['mean']:.3g} (band of the mean {lo:.3g}-{hi:.3g}); "
                             f"{100 * n['in_band_fraction']:.0f} % of ticks in band")
        ax.axhline(n.get("dof", 1), color="k", ls=":", lw=0.8)
        ax.set_ylabel(title)
        ax.legend(fontsize=7, loc="upper left")
    axes[0].set_title("Filter consistency: NEES against its own covariance (dotted: the dof, expected mean)")
    axes[1].set_xlabel("dive time (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


FUSION_COLOURS = {"fused": "tab:blue", "fused_deweighted": "tab:purple", "gate": "tab:red",
                  "mag_disturbance": "tab:orange", "unusable": "k"}


def read_fusion(run):
    """fusion.csv of a replay (board/replay/fusion_csv.h): one row per measurement the filter judged."""
    path = os.path.join(run, "fusion.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def fusion_plot(path, rows, t0):
    """Per source, in the spirit of PX4's estimator_aid_src_*: the innovation test ratio (<= 1 passes) and
    each innovation component normalised by the square root of its variance (diag of S) over time, coloured
    by what the filter did; the compass's magnetic-disturbance state shaded (orange: refused, violet:
    de-weighted)."""
    by_source = {}
    for r in rows:
        if int(r["dim"]) > 0:
            by_source.setdefault(r["source"], []).append(r)
    if not by_source:
        return False
    sources = sorted(by_source)
    fig, axes = plt.subplots(len(sources), 2, figsize=(12, 2.2 * len(sources)), sharex=True, squeeze=False)
    for row, src in enumerate(sources):
        items = by_source[src]
        t = np.array([float(r["t_s"]) for r in items]) - t0
        reasons = [r["reason"] for r in items]
        ratio = np.array([float(r["test_ratio"]) for r in items])
        ax_r, ax_n = axes[row]
        for reason in sorted(set(reasons)):
            m = np.array([x == reason for x in reasons])
            ax_r.semilogy(t[m], np.clip(ratio[m], 1e-4, 1e4), ".", ms=1.5,
                          color=FUSION_COLOURS.get(reason, "tab:gray"), label=f"{reason} ({m.sum()})")
        ax_r.axhline(1.0, color="k", ls=":", lw=0.8)
        ax_r.set_ylabel(f"{src}\ntest ratio")
        ax_r.legend(fontsize=6, loc="upper left", markerscale=4)
        dim = max(int(r["dim"]) for r in items)
        for i in range(dim):
            nu = np.array([float(r[f"innov_{i}"]) for r in items])
            var = np.array([float(r[f"var_{i}"]) for r in items])
            ok = var > 0
            ax_n.plot(t[ok], nu[ok] / np.sqrt(var[ok]), ".", ms=1.0, label=f"component {i}")
        for k in (-3, 3):
            ax_n.axhline(k, color="k", ls=":", lw=0.8)
        ax_n.set_ylabel("innovation / sqrt(S)")
        ax_n.set_ylim(-15, 15)
        if dim > 1:
            ax_n.legend(fontsize=6, loc="upper left", markerscale=4, ncol=dim)
        if src == "heading":
            state = np.array([int(r["mag_state"]) for r in items])
            for ax in (ax_r, ax_n):
                shade_intervals(ax, t, state == 2, "tab:orange", "compass refused")
                shade_intervals(ax, t, state == 1, "tab:purple", "compass de-weighted")
    axes[0][0].set_title("Innovation test ratio per fused measurement (dotted: the gate)")
    axes[0][1].set_title("Normalised innovation (dotted: 3 sigma)")
    axes[-1][0].set_xlabel("dive time (s)")
    axes[-1][1].set_xlabel("dive time (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def accuracy_rows(summary):
    """(name, stats or None) rows: odometry-frame error beside the panel-relative one, aligned ATE."""
    panel = summary.get("panel_error") or {}
    whole = panel.get("whole") or {}
    stage2 = panel.get("stage2") or {}
    odom2 = (summary.get("odom_error") or {}).get("stage2") or {}
    ate = summary.get("ate") or {}
    return [("odometry frame: position error (m)", summary.get("position_error_m")),
            ("panel-relative: position error (m)", whole.get("position_m")),
            ("odometry frame: orientation error (deg)", summary.get("orientation_error_deg")),
            ("panel-relative: orientation error (deg)", whole.get("orientation_deg")),
            ("stage 2, odometry frame: position error (m)", odom2.get("position_m")),
            ("stage 2, panel-relative: position error (m)", stage2.get("position_m")),
            ("after SE(3) alignment (ATE): position error (m)", ate.get("position_m")),
            ("after SE(3) alignment (ATE): orientation error (deg)", ate.get("rotation_deg"))]


def scatter3d(path, csv_path, title, colour_column=None, max_points=20000):
    data = np.loadtxt(csv_path, delimiter=",", skiprows=1, ndmin=2)
    if data.size == 0:
        return False
    if len(data) > max_points:
        data = data[:: len(data) // max_points + 1]
    fig = plt.figure(figsize=(7, 6))
    ax = fig.add_subplot(projection="3d")
    c = data[:, colour_column] if colour_column is not None else data[:, 2]
    ax.scatter(data[:, 0], data[:, 1], data[:, 2], c=c, s=1, cmap="tab20" if colour_column else "viridis")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    ax.set_title(title)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return True


def markdown_table_html(text):
    """The Markdown tables of paper_tables.py as HTML (titles as headings)."""
    out, rows = [], []

    def flush():
        if rows:
            out.append("<table>" + "".join(rows) + "</table>")
            rows.clear()

    for line in text.splitlines():
        if line.startswith("|"):
            cells = [c.strip() for c in line.strip("|").split("|")]
            if all(set(c) <= {"-"} for c in cells):
                continue
            tag = "th" if not rows else "td"
            rows.append("<tr>" + "".join(f"<{tag}>{html.escape(c)}</{tag}>" for c in cells) + "</tr>")
        else:
            flush()
            if line.strip():
                out.append(f"<h3>{html.escape(line)}</h3>")
    flush()
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", required=True, help="main replay output directory (EKF-adaptive)")
    ap.add_argument("--compare", action="append", default=[], help="NAME=DIR of another setting for Fig. 5")
    ap.add_argument("--tables", help="Markdown tables from paper_tables.py")
    ap.add_argument("--figures", help="output directory of deepnav-figures")
    ap.add_argument("--threshold", type=float, default=0.45, help="modality threshold drawn under m_I")
    ap.add_argument("--out", required=True, help="report directory")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.run, "summary.json")) as f:
        summary = json.load(f)
    figures, rows = [], []
    frames = read_frames(args.run)
    if os.path.exists(os.path.join(args.run, "truth.tum")):
        t, p, p_true, pos_err, _ = errors(args.run)
        top_view(os.path.join(args.out, "top_view.png"), p, p_true, pos_err)
        runs = {"EKF-adaptive (T_L2)": args.run}
        for item in args.compare:
            name, _, path = item.partition("=")
            runs[name] = path
        fig5(os.path.join(args.out, "fig5.png"), runs, frames, args.threshold, t[0])
        figures += ["top_view.png", "fig5.png"]
        rows = accuracy_rows(summary)
        if os.path.exists(os.path.join(args.run, "nees.csv")) and nees_plot(
                os.path.join(args.out, "nees.png"), args.run, summary, t[0]):
            figures.append("nees.png")
        fusion = read_fusion(args.run)
        if fusion and fusion_plot(os.path.join(args.out, "fusion.png"), fusion, t[0]):
            figures.append("fusion.png")
    if args.figures and os.path.isdir(args.figures):
        for name in ("left.png", "disparity.png", "planes.png"):
            src = os.path.join(args.figures, name)
            if os.path.exists(src):
                shutil.copy(src, os.path.join(args.out, name))
                figures.append(name)
        cloud = os.path.join(args.figures, "cloud_planes.csv")
        if os.path.exists(cloud) and scatter3d(os.path.join(args.out, "cloud_planes.png"), cloud,
                                               "filtered cloud (camera frame), colour: plane", 3):
            figures.append("cloud_planes.png")
        voxels = os.path.join(args.figures, "octomap_voxels.csv")
        if os.path.exists(voxels) and scatter3d(os.path.join(args.out, "octomap.png"), voxels,
                                                "stage-1 workspace octomap (occupied voxels, odom)"):
            figures.append("octomap.png")
    table = "".join(
        f"<tr><td>{html.escape(name)}</td><td>{s['mean']:.3f}</td><td>{s['std']:.3f}</td>"
        f"<td>{s['rms']:.3f}</td><td>{s['max']:.3f}</td></tr>" if s else
        f"<tr><td>{html.escape(name)}</td><td colspan=4>n/a</td></tr>" for name, s in rows)
    if summary.get("panel_error") is None and summary.get("panel_error_absent"):
        table += f"<tr><td colspan=5>panel-relative: {html.escape(summary['panel_error_absent'])}</td></tr>"
    loop = summary["loop"]
    tasks = "".join(
        f"<tr><td>{html.escape(tk['name'])}</td><td>{tk['runs']}</td><td>{tk['overruns']}</td>"
        f"<td>{tk['mean_us']:.1f}</td><td>{tk['max_us']}</td></tr>" for tk in loop["tasks"])
    speed = summary["dive_s"] / summary["wall_s"] if summary["wall_s"] > 0 else math.inf
    tables = ""
    if args.tables and os.path.exists(args.tables):
        with open(args.tables) as f:
            tables = markdown_table_html(f.read())
    page = f"""<!doctype html><html><head><meta charset="utf-8"><title>deepnav dive report</title>
<style>body{{font-family:sans-serif;max-width:1000px;margin:auto}}td,th{{padding:2px 8px;text-align:right}}
table{{border-collapse:collapse}}tr:nth-child(even){{background:#f4f4f4}}</style>
</head><body><h1>deepnav dive report</h1>
<p>Main run (EKF-adaptive, T_L2): dive {summary['dive_s']:.1f} s replayed in {summary['wall_s']:.2f} s
({speed:.1f}x real time); {summary['ticks']} loop ticks; stage 2 from {summary.get('stage2_at_s', -1):.1f} s;
smoothness m<sub>A</sub> = {summary['smoothness_m_a']:.4f}.</p>
<h2>Accuracy against ground truth</h2><table><tr><th></th><th>mean</th><th>std</th><th>rms</th><th>max</th></tr>{table}</table>
<h2>The paper's tables</h2>{tables}
<h2>Loop</h2><table><tr><th>task</th><th>runs</th><th>overruns</th><th>mean µs</th><th>max µs</th></tr>{tasks}</table>
<p>Inputs: {html.escape(json.dumps(summary['inputs']))}</p>
<p>VO: {html.escape(json.dumps(summary.get('vo', {})))}; workspace: {html.escape(json.dumps(summary.get('workspace', {})))}</p>
<h2>Figures</h2>
{''.join(f'<p><img src="{f}" style="max-width:100%"><br>{html.escape(f)}</p>' for f in figures)}
</body></html>"""
    with open(os.path.join(args.out, "index.html"), "w") as f:
        f.write(page)


if __name__ == "__main__":
    main()
