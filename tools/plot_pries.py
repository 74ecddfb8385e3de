#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Plots `hemoscale validate pries` (pries_validation.csv or .csv.gz): Ht_d/Ht_c and mu_rel vs diameter, simulation
vs Pries 1992, the simulated points with their seeds' standard error. Usage: /usr/bin/python3 tools/plot_pries.py pries_validation.csv OUT.png"""
import argparse

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = hs_tables.read_rows(csv_path)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ht in sorted({r["tube_hematocrit_requested"] for r in rows}, key=float):
        sel = sorted((r for r in rows if r["tube_hematocrit_requested"] == ht), key=lambda r: float(r["diameter_um"]))
        d = [float(r["diameter_um"]) for r in sel]
        h = float(ht)
        achieved = [float(r["tube_hematocrit"]) for r in sel]
        # Error bars: the seeds' standard error (columns *_se, since 2026-12-02; absent in older tables).
        ht_se = [float(r.get("discharge_hematocrit_se", 0) or 0) / a for r, a in zip(sel, achieved)]
        mu_se = [float(r.get("relative_apparent_viscosity_se", 0) or 0) for r in sel]
        line = axes[0].errorbar(d, [float(r["discharge_hematocrit"]) / a for r, a in zip(sel, achieved)], yerr=ht_se,
                                fmt="o-", capsize=3, label=f"CFD-DEM Ht_c={h:.2f}")[0]
        axes[0].plot(d, [float(r["pries_discharge_hematocrit"]) / a for r, a in zip(sel, achieved)], "s--", color=line.get_color(),
                     mfc="none", label=f"Pries 1992 Ht_c={h:.2f}")
        axes[1].errorbar(d, [float(r["relative_apparent_viscosity"]) for r in sel], yerr=mu_se, fmt="o-", capsize=3,
                         color=line.get_color())
        axes[1].plot(d, [float(r["pries_relative_apparent_viscosity"]) for r in sel], "s--", color=line.get_color(), mfc="none")
    axes[0].set_xlabel("tube diameter D (um)")
    axes[0].set_ylabel("Ht_d / Ht_c (Fahraeus effect)")
    axes[1].set_xlabel("tube diameter D (um)")
    axes[1].set_ylabel("relative apparent viscosity mu_rel")
    axes[0].legend(fontsize=7)
    for ax in axes:
        ax.set_xscale("log")
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv", help="pries_validation.csv (or .csv.gz) of `hemoscale validate pries`")
    p.add_argument("png", help="PNG to write")
    a = p.parse_args()
    main(a.csv, a.png)
