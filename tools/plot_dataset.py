#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""DI, Cd and Cl of the resolved dataset against their inputs (the seed paper's Fig. 11 style): DI vs gamma+ coloured
by u_r+, Cd and Cl vs Re_p coloured by DI. The dataset may be a .csv or a .csv.gz.
Usage: /usr/bin/python3 tools/plot_dataset.py data/resolved/dataset.csv [OUT.png]"""
import argparse
import math

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("dataset", help="dataset.csv (or .csv.gz) of a campaign")
    p.add_argument("out", nargs="?", default="dataset.png", help="PNG to write (default dataset.png)")
    a = p.parse_args()
    rows = hs_tables.read_rows(a.dataset)
    out = a.out
    col = {k: [hs_tables.number(r[k]) for r in rows] for k in ("gamma_plus", "u_r_plus", "re_p", "di", "cd", "cl")}
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    panels = ((axes[0], "gamma_plus", "di", "u_r_plus", "gamma+", "DI", "u_r+"),
              (axes[1], "re_p", "cd", "di", "Re_p", "C_d", "DI"),
              (axes[2], "re_p", "cl", "di", "Re_p", "C_l", "DI"))
    for ax, x, y, c, xl, yl, cl in panels:
        pts = [(a, b, d) for a, b, d in zip(col[x], col[y], col[c]) if all(map(math.isfinite, (a, b, d)))]
        if pts:
            s = ax.scatter([p[0] for p in pts], [p[1] for p in pts], c=[p[2] for p in pts], cmap="viridis")
            fig.colorbar(s, ax=ax, label=cl)
        ax.set_xlabel(xl)
        ax.set_ylabel(yl)
        ax.set_title(f"{len(pts)} of {len(rows)} rows", fontsize=9)
    # Stokes drag: C_d ~ 1 / Re_p, a straight line of slope -1 on log axes.
    axes[1].set_xscale("log")
    axes[1].set_yscale("log")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
