#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Report of a `hemoscale fit` run folder: data vs model, residuals, Pareto front -> report.png.
Usage: /usr/bin/python3 tools/plot_fit.py RUN_DIR"""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    header, body = rows[0], [[float(x) for x in r] for r in rows[1:] if r]
    return header, body


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
    run_dir = sys.argv[1]
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
    fig.savefig(os.path.join(run_dir, "report.png"), dpi=110)


if __name__ == "__main__":
    main()
