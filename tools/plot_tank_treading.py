#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The resolved cell in shear against Fischer & Korzeniewski 2015: tank-treading frequency f / gamma_dot vs the
experiment's shear rate (single cells, bin means +- SD, the model's healthy cell and its viscosity-ratio-1 rerun) and
the inclination vs shear rate in the 10.7 and 104 mPa s media (donors and model), from the JSON of
`hemoscale validate tank-treading --json FILE` (which also calls this script).
Usage: /usr/bin/python3 tools/plot_tank_treading.py RESULT.json REFERENCE_DIR OUT.png"""
import argparse
import json
import os

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("result", help="JSON of validate tank-treading")
    p.add_argument("reference", help="data/reference (fischer_korzeniewski2015_*.csv)")
    p.add_argument("out", help="PNG to write")
    a = p.parse_args()
    with open(a.result) as f:
        r = json.load(f)
    cells = hs_tables.read_columns(os.path.join(a.reference, "fischer_korzeniewski2015_ttf_cells.csv"))
    bins = hs_tables.read_columns(os.path.join(a.reference, "fischer_korzeniewski2015_ttf_binned.csv"))
    incl = hs_tables.read_columns(os.path.join(a.reference, "fischer_korzeniewski2015_inclination.csv"))
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.3))
    ax.plot(cells["shear_rate_per_s"], cells["f_over_shear_rate"], ".", color="0.75", ms=3, label="single cells")
    ax.errorbar(bins["shear_rate_mean_per_s"], bins["f_over_shear_rate_mean"], yerr=bins["f_over_shear_rate_sd"],
                fmt="s", color="k", capsize=3, label="bin mean +- SD")
    for key, style, label in (("frequency", "o-", "model, healthy cytoplasm"),
                              ("frequency_viscosity_ratio_1", "^--", "model, viscosity ratio 1")):
        rows = [x for x in r.get(key, []) if x.get("settled")]
        if rows:
            ax.plot([x["shear_rate_experiment_1_s"] for x in rows], [x["f_over_shear_rate"] for x in rows], style,
                    label=label)
    ax.set_xscale("log")
    ax.set_xlabel("shear rate in 28.9 mPa s (1/s)")
    ax.set_ylabel("f / shear rate")
    ax.set_title("tank-treading frequency")
    ax.legend(fontsize=8)
    for eta, colour in ((10.7, "tab:blue"), (104.0, "tab:red")):
        pick = [i for i, e in enumerate(incl["eta_o_mPa_s"]) if abs(e - eta) < 1e-9]
        bx.plot([incl["shear_rate_per_s"][i] for i in pick], [incl["angle_deg"][i] for i in pick], ".", color=colour,
                alpha=0.35, label=f"donors, {eta:g} mPa s")
        rows = [x for x in r.get("inclination", []) if abs(x["eta_o_mPa_s"] - eta) < 1e-9 and x.get("settled")]
        if rows:
            bx.errorbar([x["shear_rate_experiment_1_s"] for x in rows], [x["inclination_deg"] for x in rows],
                        yerr=[x["swinging_amplitude_deg"] for x in rows], fmt="o-", color=colour, capsize=3,
                        label=f"model (bar: swing), {eta:g} mPa s")
    bx.set_xscale("log")
    bx.set_xlabel("shear rate (1/s)")
    bx.set_ylabel("inclination (deg)")
    bx.set_title("tank-treading inclination")
    bx.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=130)


if __name__ == "__main__":
    main()
