#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Report of a `hemoscale fit` run folder: data vs model, residuals, Pareto front -> report.png.
predictions.csv and pareto.csv may also be archived as .csv.gz.
Usage: /usr/bin/python3 tools/plot_fit.py RUN_DIR [-o OUT.png]   (default RUN_DIR/report.png)"""
import argparse
import glob
import os

import matplotlib

import hs_tables

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    return hs_tables.read_matrix(hs_tables.locate(path))


def closure_text(run_dir):
    for path in glob.glob(os.path.join(run_dir, "*.toml")):
        if os.path.basename(path) == "fit.toml":
            continue
        with open(path) as f:
            lines = f.read().splitlines()
        get = lambda k: next((l.split("=", 1)[1].strip().strip('"') for l in lines if l.startswith(k + " ")), "")
        return get("output"), get("expression")
    return "y", ""


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run_dir", help="folder of a `hemoscale fit` run (predictions.csv, pareto.csv, the closure .toml)")
    p.add_argument("-o", "--output", help="PNG to write (default RUN_DIR/report.png)")
    a = p.parse_args()
    run_dir = a.run_dir
    header, rows = read_csv(os.path.join(run_dir, "predictions.csv"))
    target = header[1]
    test = [r for r in rows if r[0] > 0.5]
    train = [r for r in rows if r[0] <= 0.5]
    output, expression = closure_text(run_dir)
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    for part, label, marker in ((train, "train", "o"), (test, "test", "s")):
        ax[0].scatter([r[1] for r in part], [r[2] for r in part], s=14, marker=marker, label=label)
        ax[1].scatter([r[1] for r in part], [r[2] - r[1] for r in part], s=14, marker=marker, label=label)
    lo, hi = min(r[1] for r in rows), max(r[1] for r in rows)
    ax[0].plot([lo, hi], [lo, hi], "k--", lw=1)
    ax[0].set(xlabel=f"data {target}", ylabel=f"model {output}", title="data vs model")
    ax[1].axhline(0.0, color="k", lw=1)
    ax[1].set(xlabel=f"data {target}", ylabel="model - data", title="residuals")
    ax[0].legend()
    _, front = read_csv(os.path.join(run_dir, "pareto.csv"))
    # Exact fits have loss 0: draw them at 1e-16 of the largest loss (round-off level) instead of -inf.
    floor = 1e-16 * max([r[1] for r in front] + [r[2] for r in front] + [1e-300])
    ax[2].semilogy([r[0] for r in front], [max(r[1], floor) for r in front], "o-", label="train loss")
    ax[2].semilogy([r[0] for r in front], [max(r[2], floor) for r in front], "s--", label="CV loss")
    ax[2].set(xlabel="complexity (nodes)", ylabel="loss (floored at 1e-16 of max)", title="Pareto front")
    ax[2].legend()
    fig.suptitle(f"{output} = {expression}" if len(expression) < 120 else f"{output} = {expression[:117]}...", fontsize=9)
    fig.tight_layout()
    fig.savefig(a.output or os.path.join(run_dir, "report.png"), dpi=110)


if __name__ == "__main__":
    main()
