#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# Axial and transverse RBC diameters vs force (stretching.csv of a run) over the Mills et al. 2004 band.
# Usage: /usr/bin/python3 tools/plot_stretching.py RUN/stretching.csv BAND.csv OUT.png [RUN2/stretching.csv LABEL2]
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    run, band, out = read(sys.argv[1]), read(sys.argv[2]), sys.argv[3]
    f = band["force_pN_digitized"]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for name, colour in (("axial", "tab:blue"), ("transverse", "tab:red")):
        ax.fill_between(f, band[f"{name}_lower_um"], band[f"{name}_upper_um"], color=colour, alpha=0.18,
                        label=f"Mills 2004 {name} (scatter)")
        ax.plot(f, band[f"{name}_mid_um"], ":", color=colour)
        ax.plot([x * 1e12 for x in run["force_N"]], [x * 1e6 for x in run[f"{name}_m"]], "o-", color=colour,
                label=f"npFEM {name}")
    if len(sys.argv) > 5:
        extra = read(sys.argv[4])
        for name in ("axial", "transverse"):
            ax.plot([x * 1e12 for x in extra["force_N"]], [x * 1e6 for x in extra[f"{name}_m"]], "s--", color="k",
                    mfc="none", label=f"{sys.argv[5]} {name}")
    ax.set_xlabel("force (pN)")
    ax.set_ylabel("diameter (um)")
    ax.set_title("RBC optical-tweezers stretching")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=130)


if __name__ == "__main__":
    main()
