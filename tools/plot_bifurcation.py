#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Draws `hemoscale study bifurcation` (bifurcation_table.json) as the seed paper's section 4.3 figures:
bifurcation_di_sh.png (Fig. 15: DI_av and S_H vs alpha, +- 1 standard error), bifurcation_di_histograms.png (Fig. 16:
per angle a top view of the cells coloured by DI, from the run's last particles frame, beside the DI histogram of
each branch) and bifurcation_profiles.png (H(w) across each branch's cut, +- 1 standard error).
Usage: /usr/bin/python3 tools/plot_bifurcation.py bifurcation_table.json OUT_DIR"""
import argparse
import json
import os
import re
import struct

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

BRANCHES = ("parent", "outlet", "daughter")


def angles(table):
    keys = sorted((k for k in table if re.fullmatch(r"angle_\d+", k)), key=lambda k: int(k.split("_")[1]))
    return [(int(k.split("_")[1]), table[k]) for k in keys]


def last_particles(run_folder):
    """Points (x, y) and deformation_index of the last frame in particles.pvd (appended raw VTK polydata), or None."""
    pvd = os.path.join(run_folder, "particles.pvd")
    if not os.path.exists(pvd):
        return None
    files = re.findall(r'file="([^"]+)"', open(pvd).read())
    if not files:
        return None
    data = open(os.path.join(run_folder, files[-1]), "rb").read()
    head = data[: data.index(b"<AppendedData")].decode()
    raw = data[data.index(b"_", data.index(b"<AppendedData")) + 1:]
    offsets = {m.group(1): int(m.group(2)) for m in re.finditer(r'Name="([^"]+)"[^>]*offset="(\d+)"', head)}

    def array(name):
        at = offsets[name]
        nbytes = struct.unpack_from("<Q", raw, at)[0]
        return struct.unpack_from(f"<{nbytes // 8}d", raw, at + 8)

    pts = array("Points")
    return pts[0::3], pts[1::3], array("deformation_index")


def fig15(rows, out, coarse=None):
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.6))
    a = [r[0] for r in rows]
    ax[0].errorbar(a, [r[1]["di_av"] for r in rows], yerr=[r[1]["di_av_se"] for r in rows], fmt="o-", capsize=3, label="dx 3 um")
    if coarse:   # the mesh check at 90 deg
        ax[0].errorbar([90], [coarse["di_av"]], yerr=[coarse["di_av_se"]], fmt="kx", capsize=3, label="dx 3.75 um")
        for branch in ("daughter", "outlet"):
            ax[1].errorbar([90], [coarse[f"s_h_{branch}"]], yerr=[coarse[f"s_h_{branch}_se"]], fmt="kx", capsize=3)
        ax[0].legend()
    ax[0].set_xlabel("bifurcation angle alpha (deg)")
    ax[0].set_ylabel("DI_av (all cells, steady window)")
    for branch, style in (("daughter", "o-"), ("outlet", "s--")):
        ax[1].errorbar(a, [r[1][f"s_h_{branch}"] for r in rows], yerr=[r[1][f"s_h_{branch}_se"] for r in rows], fmt=style,
                       capsize=3, label=branch + (" (x: dx 3.75 um)" if coarse and branch == "outlet" else ""))
    ax[1].set_xlabel("bifurcation angle alpha (deg)")
    ax[1].set_ylabel("hematocrit skewness S_H at the cut")
    ax[1].legend()
    for x in ax:
        x.set_xticks(a)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bifurcation_di_sh.png"), dpi=130)


def fig16(rows, out):
    fig, ax = plt.subplots(len(rows), 2, figsize=(10, 3.2 * len(rows)), squeeze=False)
    for i, (alpha, r) in enumerate(rows):
        di = r["statistics"]["di"]
        cells = last_particles(r.get("run_folder", ""))
        if cells:
            sc = ax[i][0].scatter([x * 1e6 for x in cells[0]], [y * 1e6 for y in cells[1]], c=cells[2], s=6, cmap="viridis")
            fig.colorbar(sc, ax=ax[i][0], label="DI")
        ax[i][0].set_aspect("equal")
        ax[i][0].set_title(f"alpha = {alpha} deg: cells at the end of the run (top view)")
        ax[i][0].set_xlabel("x (um)")
        ax[i][0].set_ylabel("y (um)")
        width = (di["range"][1] - di["range"][0]) / di["bins"]
        for b in BRANCHES:
            n = di[b]["cell_samples"]
            if n:
                ax[i][1].step(di["bin_centres"], [c / n / width for c in di[b]["counts"]], where="mid",
                              label=f"{b}: DI_av {di[b]['di_av']:.4f}")
        ax[i][1].axvline(di["threshold"], color="k", lw=0.8, ls=":")
        used = [k for k in range(di["bins"]) if di["all"]["counts"][k]]
        if used:   # the bins that hold cells, and two either side
            lo, hi = max(0, used[0] - 2), min(di["bins"] - 1, used[-1] + 2)
            ax[i][1].set_xlim(di["bin_centres"][lo] - width, di["bin_centres"][hi] + width)
        ax[i][1].set_xlabel("DI")
        ax[i][1].set_ylabel("probability density")
        ax[i][1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bifurcation_di_histograms.png"), dpi=110)


def profiles(rows, out):
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.6), sharey=True)
    for j, branch in enumerate(("daughter", "outlet")):
        for alpha, r in rows:
            p = r["statistics"]["branches"][branch]
            ax[j].errorbar(p["w"], p["hematocrit"], yerr=p["hematocrit_se"], fmt="o-", ms=3, capsize=2,
                           label=f"{alpha} deg: S_H {p['s_h']:.3f}")
        ax[j].set_title(f"{branch} branch, cut 2 D past the junction")
        ax[j].set_xlabel("w across the cut (0: right of the flow, 1: left)")
        ax[j].legend(fontsize=8)
    ax[0].set_ylabel("H(w) (cell centres, steady window)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bifurcation_profiles.png"), dpi=130)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("table", help="bifurcation_table.json of `hemoscale study bifurcation`")
    p.add_argument("out_dir", help="folder for the three PNGs")
    args = p.parse_args()
    table = json.load(open(args.table))
    rows = angles(table)
    if not rows:
        raise SystemExit(f"{args.table}: no angle_* entries")
    os.makedirs(args.out_dir, exist_ok=True)
    fig15(rows, args.out_dir, table.get("angle_90_coarse"))
    fig16(rows, args.out_dir)
    profiles(rows, args.out_dir)


if __name__ == "__main__":
    main()
