#!/usr/bin/env python3
"""Plots of pf_accuracy results (docs/accuracy.md): for each knob, every case's accuracy metric
against GPU milliseconds per frame, and for each case the Pareto front over all configurations.

usage: scripts/plot_accuracy.py RESULTS.json [RESULTS_2.json ...] OUTDIR
Several result files (e.g. two grid resolutions) are drawn together, labelled by their cell count.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import NullFormatter, ScalarFormatter  # noqa: E402

# One panel per (case, metric); every metric's absolute value, smaller is better, except the
# amplitude lost per period, where a negative value is a growing wave: not drawn, but named in
# the panel (NEGATIVE_FAILS).
PANELS = [
    ("hydrostatic", "spurious_speed", "spurious speed / sqrt(g dx)"),
    ("rotation", "angular_momentum_loss_pct", "angular momentum lost, %"),
    ("closed_box", "kinetic_energy_loss_pct", "kinetic energy lost, %"),
    ("standing_wave", "period_error_pct", "|period error|, %"),
    # Issue 17: the wave's damping, 3D and thin, and the largest rise of its energy.
    ("standing_wave", "amplitude_loss_per_period_pct", "amplitude lost per period, %"),
    ("standing_wave_thin", "amplitude_loss_per_period_pct", "amplitude lost per period, %"),
    ("standing_wave", "energy_gain_max_pct", "energy rise, max, % of the wave's"),
    ("standing_wave_thin", "energy_gain_max_pct", "energy rise, max, % of the wave's"),
    # Mass over density (pf_stats.liquid_volume): the capped count sum (volume_drift_pct) also
    # reads the spread of particle counts as loss (docs/design.md §4.11).
    ("dam_break", "liquid_volume_drift_pct", "|liquid volume drift|, %"),
]


NEGATIVE_FAILS = {"amplitude_loss_per_period_pct"}

FLOOR = 1e-6


def load(paths):
    rows = []
    for path in paths:
        with open(path) as f:
            data = json.load(f)
        for row in data["results"]:
            row["n"] = data["cells"]
            rows.append(row)
    return rows


def value(row, metric):
    v = row["metrics"].get(metric)
    if v is not None and metric in NEGATIVE_FAILS and v < 0:
        return None
    # NaN: no period measured. Exact zeros (a tank that starts in equilibrium stays there) are
    # drawn at the floor of the log axis.
    return None if v is None or v != v else max(abs(v), FLOOR)


def growing(rows, case, metric):
    """'config (n³)' of the rows whose wave grew: not drawn on a log axis, so named instead."""
    if metric not in NEGATIVE_FAILS:
        return []
    return [f'{r["config"]} ({r["n"]}³)' for r in rows
            if r["case"] == case and (r["metrics"].get(metric) or 0) < 0]


def style(ax, panel, grown=()):
    case, _, label = panel
    if grown:
        ax.text(0.02, 0.98, "grows, not drawn: " + ", ".join(grown), transform=ax.transAxes, fontsize=6,
                va="top", color="tab:red", wrap=True)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_title(case, fontsize=10)
    ax.set_xlabel("GPU ms per frame")
    ax.set_ylabel(label, fontsize=8)
    ax.grid(True, which="both", alpha=0.3)


def grid(n):
    cols = 3
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.0 * cols, 4.0 * rows), squeeze=False)
    flat = [a for row in axes for a in row]
    for a in flat[n:]:
        a.axis("off")
    return fig, flat[:n]


def pareto(points):
    """Points (ms, error) not beaten in both by another point, sorted by ms."""
    front, best = [], float("inf")
    for ms, err, label in sorted(points):
        if err < best:
            front.append((ms, err, label))
            best = err
    return front


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    rows = load(sys.argv[1:-1])
    out = sys.argv[-1]
    os.makedirs(out, exist_ok=True)
    panels = [pn for pn in PANELS if any(r["case"] == pn[0] and pn[1] in r["metrics"] for r in rows)]
    sizes = sorted({r["n"] for r in rows})
    markers = ["o", "s", "^", "D"]
    for knob in sorted({r["knob"] for r in rows}):
        fig, axes = grid(len(panels))
        for ax, (case, metric, label) in zip(axes, panels):
            for si, n in enumerate(sizes):
                pts = [r for r in rows if r["knob"] == knob and r["case"] == case and r["n"] == n
                       and value(r, metric) is not None]
                for r in pts:
                    ax.scatter(r["gpu_ms_per_frame"], value(r, metric), marker=markers[si % len(markers)])
                    ax.annotate(f'{r["config"]} ({n}³)' if len(sizes) > 1 else r["config"],
                                (r["gpu_ms_per_frame"], value(r, metric)), fontsize=7, xytext=(3, 3),
                                textcoords="offset points")
            style(ax, (case, metric, label), growing([r for r in rows if r["knob"] == knob], case, metric))
        fig.suptitle(f"knob: {knob}")
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"knob_{knob}.png"), dpi=110)
        plt.close(fig)
    fig, axes = grid(len(panels))
    for ax, (case, metric, label) in zip(axes, panels):
        for si, n in enumerate(sizes):
            pts = [(r["gpu_ms_per_frame"], value(r, metric), r["config"]) for r in rows
                   if r["case"] == case and r["n"] == n and value(r, metric) is not None]
            ax.scatter([p[0] for p in pts], [p[1] for p in pts], alpha=0.35, marker=markers[si % len(markers)],
                       label=f"{n}³ cells" if len(sizes) > 1 else None)
            front = pareto(pts)
            ax.plot([p[0] for p in front], [p[1] for p in front], "-", lw=1.2)
            for ms, err, config in front:
                ax.annotate(config, (ms, err), fontsize=7, xytext=(3, 3), textcoords="offset points")
        style(ax, (case, metric, label), growing(rows, case, metric))
        if len(sizes) > 1:
            ax.legend(fontsize=7)
    fig.suptitle("Pareto front over every configuration (lines): nothing is both faster and more accurate")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pareto.png"), dpi=110)
    plt.close(fig)
    print(f"wrote {out}/knob_*.png and {out}/pareto.png")


if __name__ == "__main__":
    main()
