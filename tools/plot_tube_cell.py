#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Cd (drag run) or Cl (lift run) and DI vs time of one tube-cell run, with the averaging window's periods and the end
of the membrane transient marked (the seed paper's Fig. 10), and the disc normal's angle from the local vorticity
(0: rolling, 90: turning in the shear plane) where the run sampled it (session 39 on). A lift run's Cd divides by its
near-zero slip: not shown.
Usage: /usr/bin/python3 tools/plot_tube_cell.py RUN_DIR [OUT.png]   (RUN_DIR holds summary.json and timeseries.csv,
       or timeseries.csv.gz as in the campaign archive data/resolved/runs/)"""
import argparse
import json
import math
import os

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run", help="run folder of a tube-cell case")
    p.add_argument("out", nargs="?", help="PNG to write (default RUN_DIR/cd_di.png)")
    a = p.parse_args()
    run = a.run
    out = a.out or os.path.join(run, "cd_di.png")
    rows = hs_tables.read_rows(hs_tables.run_file(run))
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    res = summary["results"]
    periods = int(res.get("periods_averaged", 0))
    period_ms = 1e3 * float(res.get("period_s", 0.0) or 0.0)
    what = "period average" if periods > 0 else "mean (no whole period detected)"
    t_ms = [1e3 * float(r["time_s"]) for r in rows]
    setup = res.get("setup", summary.get("setup", ""))   # results.setup; top level in runs archived before schema 1
    force = ("cl", "cl_mean", "C_l") if setup == "lift" else ("cd", "cd_mean", "C_d")
    angles = [float(r.get("normal_to_vorticity_rad") or "nan") for r in rows]
    oriented = any(a == a for a in angles)   # a NaN is not equal to itself: runs before the measure have none
    fig, axes = plt.subplots(3 if oriented else 2, 1, figsize=(7, 7.5 if oriented else 5.5), sharex=True)
    if oriented:
        axes[2].plot(t_ms, [math.degrees(a) for a in angles], color="tab:green", lw=1)
        axes[2].set_ylim(0, 90)
        axes[2].set_ylabel("disc normal vs vorticity (deg)")
        axes[2].axhspan(0, 30, color="tab:green", alpha=0.08, label="rolling")
        axes[2].axhspan(60, 90, color="tab:orange", alpha=0.08, label="in the shear plane")
        axes[2].legend(loc="best", fontsize=8)
    for ax, key, mean_key, label in ((axes[0],) + force, (axes[1], "di", "di_mean", "DI")):
        ax.plot(t_ms, [float(r[key]) for r in rows], color="tab:blue", lw=1)
        ax.axhline(res[mean_key], color="k", ls="--", lw=1, label=f"{what} {res[mean_key]:.4g}")
        ax.set_ylabel(label)
        ax.legend(loc="best", fontsize=8)
    if periods > 0 and period_ms > 0:   # the window averaged: the last `periods` whole periods
        for k in range(periods + 1):
            for ax in axes:
                ax.axvline(t_ms[-1] - k * period_ms, color="tab:red", lw=0.8, alpha=0.6)
    transient_ms = 1e3 * float(res.get("transient_s", 0.0) or 0.0)
    if transient_ms > 0:
        for ax in axes:
            ax.axvline(transient_ms, color="tab:gray", ls=":", lw=1)
        axes[1].text(transient_ms, axes[1].get_ylim()[1], " end of transient", fontsize=7, va="top", color="tab:gray")
    axes[-1].set_xlabel("time (ms)")
    axes[0].set_title(f"{setup}: Re = {res['reynolds']:.3g}, r* = {res['r_star_nominal']:.2g}, "
                      f"{res['flow_mode']}{', ' + res['disc_orientation'] if res.get('disc_orientation') else ''}, {periods} periods of {period_ms:.3g} ms (red)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
