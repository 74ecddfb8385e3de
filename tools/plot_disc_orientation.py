#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The disc normal's angle from the local vorticity (0: rolling, 90: turning in the shear plane) and DI vs time of one
or more tube-cell runs, overlaid: e.g. the same case started at different disc_tilt_deg, to see which motion each start
ends in. Runs from before the orientation was sampled (session 39) have no angle and are refused.
Usage: /usr/bin/python3 tools/plot_disc_orientation.py RUN_DIR [RUN_DIR ...] --out OUT.png
       (each RUN_DIR holds timeseries.csv, or timeseries.csv.gz as in the campaign archive, and summary.json once the run
       has ended: a run still going can be drawn too)"""
import argparse
import json
import math
import os
import sys

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+", help="run folders of tube-cell cases")
    p.add_argument("--out", required=True, help="PNG to write")
    a = p.parse_args()
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    for run in a.runs:
        rows = hs_tables.read_rows(hs_tables.run_file(run))
        if not rows or "normal_to_vorticity_rad" not in rows[0]:
            sys.exit(f"{run}: its time series has no normal_to_vorticity_rad column (a run from before session 39)")
        summary = os.path.join(run, "summary.json")   # absent while a run goes on, or after it was stopped
        res = {"disc_orientation": "running or stopped"}
        if os.path.isfile(summary):
            with open(summary) as f:
                res = json.load(f)["results"]
        t_ms = [1e3 * float(r["time_s"]) for r in rows]
        angles = [math.degrees(float(r["normal_to_vorticity_rad"])) for r in rows]
        start = next((x for x in angles if x == x), float("nan"))   # the first sampled angle
        name = os.path.basename(os.path.normpath(run))
        if name in ("result", "out", "output"):   # an archived check's result/ or a case's output/: its parent names it
            name = os.path.basename(os.path.dirname(os.path.normpath(run)))
        label = (f"{name}: start {start:.0f} deg, "
                 f"{res.get('disc_orientation') or 'unclassified'}")
        axes[0].plot(t_ms, angles, lw=1, label=label)
        axes[1].plot(t_ms, [float(r["di"]) for r in rows], lw=1)
    axes[0].axhspan(0, 30, color="tab:green", alpha=0.08)
    axes[0].axhspan(60, 90, color="tab:orange", alpha=0.08)
    axes[0].set_ylim(0, 90)
    axes[0].set_ylabel("disc normal vs vorticity (deg)")
    axes[0].set_title("green band: rolling; orange band: turning in the shear plane", fontsize=9)
    axes[0].legend(loc="best", fontsize=7)
    axes[1].set_ylabel("DI")
    axes[1].set_xlabel("time (ms)")
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print(a.out)


if __name__ == "__main__":
    main()
