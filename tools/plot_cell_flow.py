#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Plots of the single-RBC plate cases from their run folders (timeseries.csv or .csv.gz, summary.json).
Usage: /usr/bin/python3 tools/plot_cell_flow.py shear RUN_DIR [-o shear.png]
         DI and inclination vs time (tumbling half turns and the Jeffery period in the title).
       /usr/bin/python3 tools/plot_cell_flow.py migration RUN_DIR [RUN_DIR ...] [-o migration.png]
         lateral position y/H vs time, one line per run (Re from its summary)."""
import argparse
import json
import math
import os

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_series(run_dir):
    return hs_tables.read_columns(hs_tables.run_file(run_dir))


def read_results(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        return json.load(f).get("results", {})


def plot_shear(run_dir, png):
    s, r = read_series(run_dir), read_results(run_dir)
    t_ms = [t * 1e3 for t in s["time_s"]]
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    ax1.plot(t_ms, s["di"], color="C0")
    ax1.set_ylabel("DI = (L - B)/(L + B)")
    ax2.plot(t_ms, [math.degrees(a) for a in s["inclination_rad"]], color="C1")
    ax2.set_ylabel("inclination (deg)")
    ax2.set_xlabel("time (ms)")
    ax2.set_ylim(-95, 95)
    title = "shear: {}, Ca = {:.3g}, gamma_dot = {:.4g} 1/s".format(r.get("flow_mode", "?"), r.get("ca", float("nan")),
                                                                     r.get("shear_rate_1_s", float("nan")))
    if r.get("tumbling_period_s", 0) > 0:
        title += "\nT = {:.4g} ms vs Jeffery {:.4g} ms ({} half turns)".format(
            1e3 * r["tumbling_period_s"], 1e3 * r["jeffery_period_s"], r.get("tumbling_half_turns", 0))
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def plot_migration(run_dirs, png):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for d in sorted(run_dirs, key=lambda d: read_results(d).get("reynolds", 0.0)):
        s, r = read_series(d), read_results(d)
        ax.plot([t * 1e3 for t in s["time_s"]], s["y_over_h"], label="Re = {:g} (Ca_wall = {:.2g})".format(
            r.get("reynolds", float("nan")), r.get("ca", float("nan"))))
    ax.axhline(0.5, color="k", lw=0.8, ls="--", label="centreline")
    ax.set_xlabel("time (ms)")
    ax.set_ylabel("lateral position y / H")
    ax.legend()
    ax.set_title("RBC migration in plane Poiseuille flow")
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("case", choices=["shear", "migration"])
    p.add_argument("runs", nargs="+")
    p.add_argument("-o", "--output")
    a = p.parse_args()
    png = a.output or os.path.join(a.runs[0], a.case + ".png")
    if a.case == "shear":
        plot_shear(a.runs[0], png)
    else:
        plot_migration(a.runs, png)
    print(png)


if __name__ == "__main__":
    main()
