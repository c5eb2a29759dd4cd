#!/usr/bin/env python3
"""The scaling plot of docs/performance.md: GPU ms per 1/60 s frame against particles, log-log, one
line per preset, from pf_bench JSON results of the scaling family (scripts/make_scaling_scenes.py).
Prints the same numbers as a Markdown table.

usage: scripts/plot_scaling.py OUT.png PRESET=RESULTS.json [PRESET=RESULTS.json ...]
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(path):
    with open(path) as f:
        doc = json.load(f)
    rows = []
    for s in doc["scenes"]:
        if "error" in s:
            continue
        rows.append({
            "scene": s["scene"],
            "particles": s["particles"],
            "ms": s["gpu"]["total_ms_per_step"]["median"],
            "substeps": s["substeps_per_step"]["mean"],
            "flags": s.get("flags", []),
            "memory_mib": s.get("gpu_memory", {}).get("bytes", 0) / 2**20,
        })
    return doc["gl"]["renderer"], sorted(rows, key=lambda r: r["particles"])


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    renderer = ""
    table = []
    for arg in sys.argv[2:]:
        preset, path = arg.split("=", 1)
        renderer, rows = load(path)
        ax.loglog([r["particles"] for r in rows], [r["ms"] for r in rows], "o-", label=preset)
        for r in rows:
            table.append((preset, r))
    lo, hi = ax.get_xlim()
    ax.axhline(16.7, color="grey", lw=0.8, ls="--")
    ax.text(lo * 1.1, 16.7 * 1.08, "16.7 ms (60 fps)", color="grey", fontsize=8)
    ax.set_xlabel("particles (8 per cell)")
    ax.set_ylabel("GPU ms per 1/60 s frame")
    ax.set_title(f"pflip scaling, {renderer.split('/')[0]}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("| preset | scene | particles | substeps | GPU ms/frame | ms per M particles | GPU memory MiB | flags |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    for preset, r in table:
        print(f"| {preset} | {r['scene']} | {r['particles']:,} | {r['substeps']:.2f} | {r['ms']:.2f} | "
              f"{r['ms'] / (r['particles'] / 1e6):.2f} | {r['memory_mib']:.0f} | {' '.join(r['flags']) or '-'} |")


if __name__ == "__main__":
    main()
