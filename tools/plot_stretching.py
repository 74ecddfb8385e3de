#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Axial and transverse RBC diameters vs force (stretching.csv of a run, or .csv.gz) over the Mills et al. 2004 band.
Usage: /usr/bin/python3 tools/plot_stretching.py RUN/stretching.csv BAND.csv OUT.png [RUN2/stretching.csv LABEL2]"""
import argparse

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    return hs_tables.read_columns(path)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run", help="stretching.csv of a run")
    p.add_argument("band", help="the Mills 2004 band (data/reference/mills2004_rbc_stretch_experiment.csv)")
    p.add_argument("out", help="PNG to write")
    p.add_argument("extra", nargs="*", metavar="RUN2 LABEL2", help="a second run's stretching.csv and its label")
    a = p.parse_args()
    if len(a.extra) not in (0, 2):
        p.error("a second run is given as RUN2/stretching.csv LABEL2")
    run, band, out = read(a.run), read(a.band), a.out
    f = band["force_pN_digitized"]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for name, colour in (("axial", "tab:blue"), ("transverse", "tab:red")):
        ax.fill_between(f, band[f"{name}_lower_um"], band[f"{name}_upper_um"], color=colour, alpha=0.18,
                        label=f"Mills 2004 {name} (scatter)")
        ax.plot(f, band[f"{name}_mid_um"], ":", color=colour)
        ax.plot([x * 1e12 for x in run["force_N"]], [x * 1e6 for x in run[f"{name}_m"]], "o-", color=colour,
                label=f"npFEM {name}")
    if a.extra:
        extra = read(a.extra[0])
        for name in ("axial", "transverse"):
            ax.plot([x * 1e12 for x in extra["force_N"]], [x * 1e6 for x in extra[f"{name}_m"]], "s--", color="k",
                    mfc="none", label=f"{a.extra[1]} {name}")
    ax.set_xlabel("force (pN)")
    ax.set_ylabel("diameter (um)")
    ax.set_title("RBC optical-tweezers stretching")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=130)


if __name__ == "__main__":
    main()
