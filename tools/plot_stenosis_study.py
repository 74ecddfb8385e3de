#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Draws `hemoscale study stenosis` (stenosis_table.json) as the seed paper's section 4.4 figures:
stenosis_di.png (Fig. 18 right: <DI>(x) of both throats on one plot, +- 1 standard error as bars and the cells'
spread as a band, the tube's wall drawn below), stenosis_side_view.png (Fig. 18 left: per throat a side view of the
cells of the run's last particles frame, projected on the x-y plane and coloured by DI) and stenosis_profiles.png
(hematocrit, mean axial cell velocity, wall shear rate and the share of cells outside the closures' validity box,
all along x).
Usage: /usr/bin/python3 tools/plot_stenosis_study.py stenosis_table.json OUT_DIR"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_bifurcation import last_particles  # noqa: E402  (the .vtp reader)

THROATS = (("throat_85um", "85 um throat", "tab:blue"), ("throat_55um", "55 um throat", "tab:red"))
UM = 1e6


def present(table):
    return [(k, label, colour, table[k]) for k, label, colour in THROATS if k in table]


def profile(row, key):
    return [b[key] for b in row["statistics"]["profile"]]


def draw_walls(ax, rows):
    for _, label, colour, row in rows:
        x = [v * UM for v in row["layout"]["bin_centres_m"]]
        r = [v * UM for v in row["layout"]["wall_radius_m"]]
        ax.plot(x, r, color=colour, label=label)
        ax.plot(x, [-v for v in r], color=colour)
    ax.set_aspect("equal")
    ax.set_xlabel("x (um)")
    ax.set_ylabel("y (um)")


def fig_di(rows, out):
    fig, (ax, geo) = plt.subplots(2, 1, figsize=(8, 6), sharex=True, gridspec_kw={"height_ratios": [2.2, 1]})
    for _, label, colour, row in rows:
        ok = [b["cell_samples"] >= 1000 for b in row["statistics"]["profile"]]
        x = [v * UM for v, k in zip(profile(row, "x_m"), ok) if k]
        m = [v for v, k in zip(profile(row, "di_mean"), ok) if k]
        se = [v for v, k in zip(profile(row, "di_mean_se"), ok) if k]
        sd = [v for v, k in zip(profile(row, "di_sd"), ok) if k]
        ax.fill_between(x, [a - b for a, b in zip(m, sd)], [a + b for a, b in zip(m, sd)], color=colour, alpha=0.15)
        ax.errorbar(x, m, yerr=se, color=colour, fmt="o-", ms=3, capsize=2, label=f"{label} (band: cells' spread)")
        ax.axvline(row["x_di_max_m"] * UM, color=colour, ls=":")
    ax.set_ylabel("<DI> = <(L - B) / (L + B)>")
    ax.legend(fontsize=8)
    ax.set_title("Cell deformation along the stenosed tube (steady window)")
    draw_walls(geo, rows)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stenosis_di.png"), dpi=130)
    plt.close(fig)


def fig_side(rows, out):
    fig, axes = plt.subplots(len(rows), 1, figsize=(9, 2.6 * len(rows)), squeeze=False)
    for ax, (_, label, colour, row) in zip(axes[:, 0], rows):
        cells = last_particles(row["run_folder"])
        if cells:
            x, y, di = cells
            sc = ax.scatter([v * UM for v in x], [v * UM for v in y], c=di, s=2, cmap="viridis")
            fig.colorbar(sc, ax=ax, label="DI")
        xs = [v * UM for v in row["layout"]["bin_centres_m"]]
        r = [v * UM for v in row["layout"]["wall_radius_m"]]
        ax.plot(xs, r, "k-", lw=1)
        ax.plot(xs, [-v for v in r], "k-", lw=1)
        ax.set_aspect("equal")
        ax.set_title(f"{label}: cells of the last frame (side view, all z)", fontsize=9)
        ax.set_xlabel("x (um)")
        ax.set_ylabel("y (um)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stenosis_side_view.png"), dpi=130)
    plt.close(fig)


def fig_profiles(rows, out):
    fig, axes = plt.subplots(2, 2, figsize=(10, 6), sharex=True)
    for _, label, colour, row in rows:
        x = [v * UM for v in profile(row, "x_m")]
        axes[0, 0].errorbar(x, profile(row, "hematocrit"), yerr=profile(row, "hematocrit_se"), color=colour, fmt="-", label=label)
        axes[0, 1].plot(x, [v * 1e3 for v in profile(row, "ux_mean_m_s")], color=colour, label=label)
        axes[1, 0].plot(x, profile(row, "wall_shear_1_s"), color=colour, label=f"{label}: measured")
        axes[1, 0].plot(x, profile(row, "wall_shear_poiseuille_1_s"), color=colour, ls="--", label=f"{label}: 4Q/(pi r^3)")
        axes[1, 1].plot(x, profile(row, "outside_any_share"), color=colour, label=f"{label}: any closure")
        axes[1, 1].plot(x, profile(row, "outside_di_share"), color=colour, ls="--", label=f"{label}: DI closure")
    axes[0, 0].set_ylabel("Ht(x)")
    axes[0, 1].set_ylabel("mean axial cell velocity (mm/s)")
    axes[1, 0].set_ylabel("wall shear rate (1/s)")
    axes[1, 1].set_ylabel("share of cells outside validity")
    for ax in axes.flat:
        ax.legend(fontsize=7)
    for ax in axes[1]:
        ax.set_xlabel("x (um)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stenosis_profiles.png"), dpi=130)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("table")
    p.add_argument("out")
    a = p.parse_args()
    table = json.load(open(a.table))
    rows = present(table)
    if not rows:
        sys.exit(f"{a.table}: no throat in the table")
    fig_di(rows, a.out)
    fig_side(rows, a.out)
    fig_profiles(rows, a.out)


if __name__ == "__main__":
    main()
