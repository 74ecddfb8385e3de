#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The neo-Hookean capsule in shear: steady Taylor deformation D vs Ca_E = mu gamma_dot a / E_s (E_s = 3 G_s), the
model's runs against Ramanujan & Pozrikidis 1998 and Doddi & Bagchi 2008 (the ranges of their steady values) and the small-Ca theory
D = (25/4) Ca_E, from the JSON of `hemoscale validate capsule --json FILE` (which also calls this script).
Usage: /usr/bin/python3 tools/plot_capsule.py RESULT.json REFERENCE.csv OUT.png"""
import argparse
import json

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("result", help="JSON of validate capsule")
    p.add_argument("reference", help="data/reference/capsule_shear_taylor_deformation.csv")
    p.add_argument("out", help="PNG to write")
    a = p.parse_args()
    with open(a.result) as f:
        runs = json.load(f)["runs"]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for source, marker in (("Ramanujan", "s"), ("Doddi", "^")):
        rows = [r for r in hs_tables.read_rows(a.reference) if r["source"].startswith(source) and r["steady"] == "true"]
        x = [float(r["ca_e"]) for r in rows]
        lo = [float(r["d_low"]) for r in rows]
        hi = [float(r["d_high"]) for r in rows]
        mid = [(u + v) / 2 for u, v in zip(lo, hi)]
        ax.errorbar(x, mid, yerr=[[m - u for m, u in zip(mid, lo)], [v - m for m, v in zip(mid, hi)]], fmt=marker,
                    mfc="none", color="grey", capsize=3, label=rows[0]["source"] if rows else source)
    ax.plot([0.0, 0.06], [0.0, 25.0 / 4.0 * 0.06], "k:", lw=1, label="D = (25/4) Ca_E (Barthes-Biesel 1980)")
    runs = sorted(runs, key=lambda r: r["ca_g"])
    ax.plot([r["ca_g"] / 3.0 for r in runs], [r["taylor_deformation"] for r in runs], "o-", color="C3", label="hemoscale")
    ax.set_xlabel("Ca_E = mu gamma_dot a / E_s")
    ax.set_ylabel("steady Taylor deformation D")
    ax.set_xlim(0.0, 0.21)
    ax.set_ylim(0.0, 0.6)
    ax.legend(fontsize=8, loc="upper left")
    ax.set_title("neo-Hookean capsule in shear, viscosity ratio 1", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)


if __name__ == "__main__":
    main()
