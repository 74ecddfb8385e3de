#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes data/synthetic/rbc_closures_synthetic.csv: a stand-in for the resolved-stage dataset, generated
from KNOWN formulas so that `hemoscale fit` can be checked to recover them. The formulas are made up (shapes
chosen to be plausible: DI saturating with shear, C_d ~ 1/Re_p, C_l ~ DI / sqrt(Re_p)); they are NOT physics.

  di = 0.6 * gamma_plus / (0.08 + gamma_plus) - 0.3 * u_r_plus
  cd = 24 / re_p * (1 + 0.5 * di)
  cl = 1.5 * di / sqrt(re_p)

Inputs are uniform on the seed paper's ranges (reference/unresolved-methods.md section 0): gamma_plus in
[0.02, 0.35], re_p in [0.01, 0.12]; u_r_plus in [-0.15, -0.01] (RBCs lag the fluid). No noise.
Usage: /usr/bin/python3 tools/make_synthetic_dataset.py [--rows 120] [--seed 20260] [--out PATH]
"""
import argparse
import os

import numpy as np


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rows", type=int, default=120)
    p.add_argument("--seed", type=int, default=20260)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p.add_argument("--out", default=os.path.join(root, "data", "synthetic", "rbc_closures_synthetic.csv"))
    a = p.parse_args()
    rng = np.random.default_rng(a.seed)
    gamma_plus = rng.uniform(0.02, 0.35, a.rows)
    u_r_plus = rng.uniform(-0.15, -0.01, a.rows)
    re_p = rng.uniform(0.01, 0.12, a.rows)
    di = 0.6 * gamma_plus / (0.08 + gamma_plus) - 0.3 * u_r_plus
    cd = 24.0 / re_p * (1.0 + 0.5 * di)
    cl = 1.5 * di / np.sqrt(re_p)
    with open(a.out, "w") as f:
        f.write(f"# synthetic stand-in for data/resolved/dataset.csv: tools/make_synthetic_dataset.py --rows {a.rows} --seed {a.seed}\n")
        f.write("# di = 0.6*gamma_plus/(0.08 + gamma_plus) - 0.3*u_r_plus; cd = 24/re_p*(1 + 0.5*di); cl = 1.5*di/sqrt(re_p)\n")
        f.write("case,gamma_plus,u_r_plus,re_p,di,cd,cl\n")
        for i in range(a.rows):
            f.write(f"{i},{gamma_plus[i]!r},{u_r_plus[i]!r},{re_p[i]!r},{di[i]!r},{cd[i]!r},{cl[i]!r}\n")


if __name__ == "__main__":
    main()
