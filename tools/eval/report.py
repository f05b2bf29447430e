#!/usr/bin/python3
"""Dive report: reads a replay output directory (summary.json, trajectory.tum, truth.tum) and writes
report/index.html with figures made by matplotlib."""
import argparse
import html
import json
import math
import os

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
    # Nearest truth orientation (truth is at the IMU rate, 10 ms apart at most from an estimate).
    idx = np.clip(np.searchsorted(tt, t), 0, len(tt) - 1)
    q_true = qt[idx]
    return t, p, p_true, np.linalg.norm(p - p_true, axis=1), quat_angle_deg(q, q_true)


def top_view(path, p, p_true, pos_err):
    fig, ax = plt.subplots(figsize=(7, 6))
    ax.plot(p_true[:, 0], p_true[:, 1], color="0.6", lw=1, label="ground truth")
    step = max(1, len(p) // 400)
    sc = ax.scatter(p[::step, 0], p[::step, 1], c=pos_err[::step], s=8 + 400 * pos_err[::step],
                    cmap="viridis", alpha=0.7, label="estimate (colour and size: position error)")
    fig.colorbar(sc, ax=ax, label="position error (m)")
    ax.set_xlabel("x east in odom (m)")
    ax.set_ylabel("y north in odom (m)")
    ax.set_aspect("equal")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), fontsize=8)
    ax.set_title("Top view of the dive")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def error_plot(path, t, pos_err, ori_err):
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 5), sharex=True)
    a1.plot(t - t[0], pos_err, lw=1)
    a1.set_ylabel("position error (m)")
    a2.plot(t - t[0], ori_err, lw=1, color="tab:red")
    a2.set_ylabel("orientation error (deg)")
    a2.set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--run", required=True, help="replay output directory")
    ap.add_argument("--out", required=True, help="report directory")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.run, "summary.json")) as f:
        summary = json.load(f)
    rows = []
    figures = []
    if os.path.exists(os.path.join(args.run, "truth.tum")):
        t, p, p_true, pos_err, ori_err = errors(args.run)
        top_view(os.path.join(args.out, "top_view.png"), p, p_true, pos_err)
        error_plot(os.path.join(args.out, "errors.png"), t, pos_err, ori_err)
        figures = ["top_view.png", "errors.png"]
        pe, oe = summary["position_error_m"], summary["orientation_error_deg"]
        rows.append(("position error (m)", pe))
        rows.append(("orientation error (deg)", oe))
    table = "".join(
        f"<tr><td>{html.escape(name)}</td><td>{s['mean']:.3f}</td><td>{s['std']:.3f}</td>"
        f"<td>{s['rms']:.3f}</td><td>{s['max']:.3f}</td></tr>" for name, s in rows)
    loop = summary["loop"]
    tasks = "".join(
        f"<tr><td>{html.escape(tk['name'])}</td><td>{tk['runs']}</td><td>{tk['overruns']}</td>"
        f"<td>{tk['mean_us']:.1f}</td><td>{tk['max_us']}</td></tr>" for tk in loop["tasks"])
    speed = summary["dive_s"] / summary["wall_s"] if summary["wall_s"] > 0 else math.inf
    page = f"""<!doctype html><html><head><meta charset="utf-8"><title>deepnav dive report</title>
<style>body{{font-family:sans-serif;max-width:900px;margin:auto}}td,th{{padding:2px 8px;text-align:right}}</style>
</head><body><h1>deepnav dive report</h1>
<p>Mode: {summary['mode']}; dive {summary['dive_s']:.1f} s replayed in {summary['wall_s']:.2f} s
({speed:.0f}x real time); {summary['ticks']} loop ticks; smoothness m<sub>A</sub> = {summary['smoothness_m_a']:.4f}.</p>
<h2>Accuracy against ground truth</h2><table><tr><th></th><th>mean</th><th>std</th><th>rms</th><th>max</th></tr>{table}</table>
<h2>Loop</h2><table><tr><th>task</th><th>runs</th><th>overruns</th><th>mean µs</th><th>max µs</th></tr>{tasks}</table>
<p>Inputs: {html.escape(json.dumps(summary['inputs']))}</p>
{''.join(f'<p><img src="{f}" style="max-width:100%"></p>' for f in figures)}
</body></html>"""
    with open(os.path.join(args.out, "index.html"), "w") as f:
        f.write(page)


if __name__ == "__main__":
    main()
