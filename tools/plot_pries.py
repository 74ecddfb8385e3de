#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Plots `hemoscale validate pries` (pries_validation.csv or .csv.gz) as the seed paper's Figs. 12-13: Ht_d/Ht_t and
mu_rel vs diameter, the simulated points with their seeds' standard error over Pries 1992's curves (--curves, the
X.pries_curves.csv that validate pries writes beside its table; without it the law is drawn at the simulated
diameters only). --baseline puts a second table beside it with open markers (the rigid-sphere table, as the paper
shows its rigid-sphere runs). Usage:
  /usr/bin/python3 tools/plot_pries.py pries.csv OUT.png [--curves pries.pries_curves.csv]
                                       [--baseline rigid/pries.csv --label "learned closures" --baseline-label "rigid spheres"]"""
import argparse

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def by_hematocrit(rows, key):
    """{hematocrit text: rows sorted by diameter}, the hematocrit read from column KEY."""
    groups = {}
    for r in rows:
        groups.setdefault(r[key], []).append(r)
    return {h: sorted(g, key=lambda r: float(r["diameter_um"])) for h, g in groups.items()}


def draw_table(axes, rows, colors, label, marker, filled):
    """The simulated entries: Ht_d / Ht_t (the achieved tube hematocrit) and mu_rel, with the seeds' standard error
    (columns *_se, since 2026-12-02; absent in older tables)."""
    for ht, sel in sorted(by_hematocrit(rows, "tube_hematocrit_requested").items(), key=lambda kv: float(kv[0])):
        color = colors.setdefault(f"{float(ht):.2f}", f"C{len(colors)}")
        d = [float(r["diameter_um"]) for r in sel]
        achieved = [float(r["tube_hematocrit"]) for r in sel]
        ht_se = [float(r.get("discharge_hematocrit_se", 0) or 0) / a for r, a in zip(sel, achieved)]
        mu_se = [float(r.get("relative_apparent_viscosity_se", 0) or 0) for r in sel]
        style = dict(fmt=marker, capsize=3, color=color, mfc=color if filled else "none", ls="none")
        axes[0].errorbar(d, [float(r["discharge_hematocrit"]) / a for r, a in zip(sel, achieved)], yerr=ht_se,
                         label=f"{label}, Ht_t={float(ht):.2f}", **style)
        axes[1].errorbar(d, [float(r["relative_apparent_viscosity"]) for r in sel], yerr=mu_se, **style)


def draw_law_at_points(axes, rows, colors):
    """Pries 1992 at the simulated diameters (older tables, no curves file)."""
    for ht, sel in by_hematocrit(rows, "tube_hematocrit_requested").items():
        color = colors.setdefault(f"{float(ht):.2f}", f"C{len(colors)}")
        d = [float(r["diameter_um"]) for r in sel]
        achieved = [float(r["tube_hematocrit"]) for r in sel]
        axes[0].plot(d, [float(r["pries_discharge_hematocrit"]) / a for r, a in zip(sel, achieved)], "--", color=color,
                     label=f"Pries 1992, Ht_t={float(ht):.2f}")
        axes[1].plot(d, [float(r["pries_relative_apparent_viscosity"]) for r in sel], "--", color=color)


def draw_curves(axes, rows, colors):
    for ht, sel in sorted(by_hematocrit(rows, "tube_hematocrit").items(), key=lambda kv: float(kv[0])):
        color = colors.setdefault(f"{float(ht):.2f}", f"C{len(colors)}")
        d = [float(r["diameter_um"]) for r in sel]
        axes[0].plot(d, [float(r["pries_ht_d_over_ht_t"]) for r in sel], "-", color=color, lw=1,
                     label=f"Pries 1992, Ht_t={float(ht):.2f}")
        axes[1].plot(d, [float(r["pries_relative_apparent_viscosity"]) for r in sel], "-", color=color, lw=1)


def main(a):
    rows = hs_tables.read_rows(a.csv)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    colors = {}   # one colour per hematocrit, shared by the law, the table and the baseline
    if a.curves:
        draw_curves(axes, hs_tables.read_rows(a.curves), colors)
    else:
        draw_law_at_points(axes, rows, colors)
    draw_table(axes, rows, colors, a.label, "o", True)
    if a.baseline:
        draw_table(axes, hs_tables.read_rows(a.baseline), colors, a.baseline_label, "s", False)
    axes[0].set_ylabel("Ht_d / Ht_t (Fahraeus effect)")
    axes[1].set_ylabel("relative apparent viscosity mu_rel")
    for ax in axes:
        ax.set_xlabel("tube diameter D (um)")
        ax.set_xscale("log")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv", help="the table of `hemoscale validate pries` (.csv or .csv.gz)")
    p.add_argument("png", help="PNG to write")
    p.add_argument("--curves", help="Pries 1992's curves (X.pries_curves.csv, written by validate pries)")
    p.add_argument("--baseline", help="a second table drawn with open squares (e.g. the rigid-sphere table)")
    p.add_argument("--label", default="CFD-DEM", help="legend label of the table (default CFD-DEM)")
    p.add_argument("--baseline-label", default="baseline", help="legend label of --baseline")
    main(p.parse_args())
