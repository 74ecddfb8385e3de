#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""D_x, D_y, D_z (= L_i / 7.82 um) of one stenosis run vs time and vs the centroid's distance from the throat, with
the constriction shaded and the wall height h(x) drawn (the seed paper's figure 7).
Usage: /usr/bin/python3 tools/plot_stenosis.py RUN_DIR [OUT.png]   (RUN_DIR holds timeseries.csv or .csv.gz and
         summary.json)
       /usr/bin/python3 tools/plot_stenosis.py RUN_DIR RUN_DIR... OUT.png   (runs overlaid vs centroid x, e.g. two
         repulsion settings; each labelled with its folder name)"""
import argparse
import json
import math
import os

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def wall_height(s, big_h, throat, length):
    """The cosine constriction of common/geometry/constriction_profile: h(s) for s = x - x_throat."""
    if abs(s) >= 0.5 * length:
        return big_h
    return big_h - 0.5 * (big_h - throat) * (1.0 + math.cos(2.0 * math.pi * s / length))


def load(run):
    rows = hs_tables.read_rows(hs_tables.run_file(run))
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    return rows, summary["results"]


def compare(runs, out):
    """D_x, D_y, D_z of several runs against the centroid's distance from the throat."""
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    styles = ("-", "--", ":", "-.")
    for k, run in enumerate(runs):
        rows, res = load(run)
        x_throat = res["throat"]["centroid_x_m"] - res["throat"]["x_minus_throat_m"]
        s_um = [1e6 * (float(r["centroid_x_m"]) - x_throat) for r in rows]
        name = os.path.basename(os.path.normpath(run))
        for key, label, colour in (("d_x", "D_x", "tab:red"), ("d_y", "D_y", "tab:blue"), ("d_z", "D_z", "tab:green")):
            ax.plot(s_um, [float(r[key]) for r in rows], color=colour, ls=styles[k % len(styles)], lw=1.2,
                    label=f"{label} {name}")
    _, res = load(runs[0])
    ax.axvspan(-0.5e6 * res["constriction_length_m"], 0.5e6 * res["constriction_length_m"], color="0.9")
    ax.axvline(0.0, color="k", ls="--", lw=0.8)
    ax.set_xlabel("centroid x - x_throat (um); constriction shaded")
    ax.set_ylabel("D_i = L_i / 7.82 um")
    ax.legend(loc="best", fontsize=7, ncol=2)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(out)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("paths", nargs="+", metavar="RUN_DIR [OUT.png]", help="one run [and the PNG], or runs then the PNG")
    a = p.parse_args()
    if len(a.paths) > 2:
        compare(a.paths[:-1], a.paths[-1])
        return
    run = a.paths[0]
    out = a.paths[1] if len(a.paths) > 1 else os.path.join(run, "stenosis_d.png")
    rows = hs_tables.read_rows(hs_tables.run_file(run))
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    res = summary["results"]
    big_h, throat, length = res["height_m"], res["throat_height_m"], res["constriction_length_m"]
    x_throat = res["throat"]["centroid_x_m"] - res["throat"]["x_minus_throat_m"]
    t_ms = [1e3 * float(r["time_s"]) for r in rows]
    s_um = [1e6 * (float(r["centroid_x_m"]) - x_throat) for r in rows]
    series = (("d_x", "D_x", "tab:red"), ("d_y", "D_y", "tab:blue"), ("d_z", "D_z", "tab:green"))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for key, label, colour in series:
        values = [float(r[key]) for r in rows]
        axes[0].plot(t_ms, values, color=colour, lw=1.2, label=label)
        axes[1].plot(s_um, values, color=colour, lw=1.2, label=label)
    # Time at which the centroid passes the throat.
    t_throat = 1e3 * res["throat"]["time_s"]
    axes[0].axvline(t_throat, color="k", ls="--", lw=0.8, label="centroid at throat")
    axes[0].set_xlabel("time (ms)")
    axes[1].axvspan(-0.5e6 * length, 0.5e6 * length, color="0.9", label="constriction")
    axes[1].axvline(0.0, color="k", ls="--", lw=0.8, label="throat")
    axes[1].set_xlabel("centroid x - x_throat (um)")
    twin = axes[1].twinx()
    xs = [s_um[0] + k * (s_um[-1] - s_um[0]) / 400.0 for k in range(401)]
    twin.plot(xs, [1e6 * wall_height(1e-6 * x, big_h, throat, length) for x in xs], color="0.5", lw=0.8, ls=":")
    twin.set_ylabel("channel height h(x) (um, dotted)", color="0.4")
    twin.set_ylim(0.0, 1.1e6 * big_h)
    for ax in axes:
        ax.set_ylabel("D_i = L_i / 7.82 um")
        ax.legend(loc="best", fontsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle(f"stenosis: throat {1e6 * throat:.3g} um of H = {1e6 * big_h:.3g} um, Re = {res['reynolds']:.3g}, "
                 f"Ca_throat = {res['ca_throat']:.3g}; D_x {res['upstream']['d_x']:.3f} upstream, "
                 f"max {res['d_x_max']:.3f} at {1e6 * res['d_x_max_at']['x_minus_throat_m']:+.1f} um, "
                 f"{res['downstream']['d_x']:.3f} downstream", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
