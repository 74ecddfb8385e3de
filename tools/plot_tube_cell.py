#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Cd (drag run) or Cl (lift run) and DI vs time of one tube-cell run, with the averaging window's periods and the end
of the membrane transient marked (the seed paper's Fig. 10). A lift run's Cd divides by its near-zero slip: not shown.
Usage: /usr/bin/python3 tools/plot_tube_cell.py RUN_DIR [OUT.png]   (RUN_DIR holds summary.json and timeseries.csv,
       or timeseries.csv.gz as in the campaign archive data/resolved/runs/)"""
import argparse
import json
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
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
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
    axes[1].set_xlabel("time (ms)")
    axes[0].set_title(f"{setup}: Re = {res['reynolds']:.3g}, r* = {res['r_star_nominal']:.2g}, "
                      f"{res['flow_mode']}, {periods} periods of {period_ms:.3g} ms (red)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
