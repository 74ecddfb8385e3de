#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Overlays the time series of several tube-cell runs of one case at different resolutions (the dx = 1 vs 0.5 um
check): Cd of the drag runs, DI, the lift force and the axial velocity of the lift runs. A run's timeseries may be
archived (.csv.gz). Usage: /usr/bin/python3 tools/plot_resolution.py OUT.png LABEL=RUN_DIR [LABEL=RUN_DIR ...]"""
import argparse
import json
import os
import re

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PANELS = (("cd", "C_d (drag runs)", "drag"), ("di", "DI", None), ("lift_N", "lift force (N, lift runs)", "lift"),
          ("axial_velocity_m_s", "axial velocity (m/s, lift runs)", "lift"))


def read_run(run_dir):
    rows = hs_tables.read_rows(hs_tables.run_file(run_dir))
    setup = ""
    summary_path = os.path.join(run_dir, "summary.json")
    if os.path.exists(summary_path):   # a run still going has no summary yet: its setup is in its resolved case
        with open(summary_path) as f:
            summary = json.load(f)   # results.setup; at the top level in runs archived before schema 1
            setup = summary.get("results", {}).get("setup", summary.get("setup", ""))
    if not setup:
        with open(os.path.join(run_dir, "case.resolved.toml")) as f:
            setup = "drag" if re.search(r'^\s*setup\s*=\s*["\']drag["\']', f.read(), re.M) else "lift"
    return rows, setup


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("out", help="PNG to write")
    p.add_argument("runs", nargs="+", metavar="LABEL=RUN_DIR", help="a run folder and its label in the legend")
    a = p.parse_args()
    if any("=" not in r for r in a.runs):
        p.error("each run is given as LABEL=RUN_DIR")
    out = a.out
    fig, axes = plt.subplots(len(PANELS), 1, figsize=(7.5, 9), sharex=True)
    colours = {}
    for arg in a.runs:
        label, run_dir = arg.split("=", 1)
        colour = colours.setdefault(label, f"C{len(colours)}")   # one colour per resolution, one line style per set-up
        rows, setup = read_run(run_dir)
        t_ms = [1e3 * float(r["time_s"]) for r in rows]
        for ax, (key, _, only) in zip(axes, PANELS):
            if only is None or only == setup:
                ax.plot(t_ms, [float(r[key]) for r in rows], lw=1, color=colour, ls="-" if setup == "lift" else "--",
                        label=f"{label} ({setup})")
    for ax, (_, ylabel, _) in zip(axes, PANELS):
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    axes[-1].set_xlabel("time (ms)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
