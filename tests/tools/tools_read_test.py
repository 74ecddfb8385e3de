#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Every tools/*.py is executable, answers --help, and reads its input from a .csv.gz: the committed campaign
archive (data/resolved/runs/*/timeseries.csv.gz) for the tube-cell plots, committed CSVs gzipped into a temporary
folder, and small tables written here for the cases that commit no output. Each plot is drawn with matplotlib's
Agg backend into the temporary folder; the test checks each PNG exists and is not empty. Exits 77 (CTest: skipped)
with a message when the tools' interpreter has no matplotlib. Usage: tools_read_test.py SOURCE_DIR"""
import gzip
import json
import os
import shutil
import subprocess
import sys
import tempfile

SKIP = 77
ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
TOOLS = os.path.join(ROOT, "tools")
ARCHIVE = os.path.join(ROOT, "data", "resolved", "runs")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(args, what):
    p = subprocess.run(args, capture_output=True, text=True, timeout=120)
    check(p.returncode == 0, f"{what} (exit {p.returncode})" + ("" if p.returncode == 0 else "\n" + p.stderr[-2000:]))
    return p


def gz_copy(src, dst):
    with open(src, "rb") as f, gzip.open(dst, "wb") as g:
        shutil.copyfileobj(f, g)
    return dst


def gz_table(path, header, rows):
    with gzip.open(path, "wt") as g:
        g.write("# written by tests/tools/tools_read_test.py\n" + ",".join(header) + "\n")
        for r in rows:
            g.write(",".join(repr(float(x)) for x in r) + "\n")
    return path


def png(tmp, name, args, what):
    out = os.path.join(tmp, name)
    run(args, what)
    check(os.path.isfile(out) and os.path.getsize(out) > 1000, f"{what}: {name} written")


def interpreter():
    with open(os.path.join(TOOLS, "plot_dataset.py")) as f:
        return f.readline()[2:].strip().split()


def plate_and_stenosis_runs(tmp):
    """Run folders of the shear, migration and stenosis cases with a gzipped timeseries (no output is committed)."""
    t = [1e-4 * k for k in range(20)]
    shear = os.path.join(tmp, "shear")
    os.makedirs(shear)
    gz_table(os.path.join(shear, "timeseries.csv.gz"), ["time_s", "di", "inclination_rad"],
             [(x, 0.3 + 0.01 * k, 0.05 * k - 0.5) for k, x in enumerate(t)])
    with open(os.path.join(shear, "summary.json"), "w") as f:
        json.dump({"results": {"flow_mode": "tumbling", "ca": 0.1, "shear_rate_1_s": 100.0}}, f)
    migration = os.path.join(tmp, "migration")
    os.makedirs(migration)
    gz_table(os.path.join(migration, "timeseries.csv.gz"), ["time_s", "y_over_h"], [(x, 0.3 + 0.005 * k) for k, x in enumerate(t)])
    with open(os.path.join(migration, "summary.json"), "w") as f:
        json.dump({"results": {"reynolds": 1.0, "ca": 0.2}}, f)
    stenosis = os.path.join(tmp, "stenosis")
    os.makedirs(stenosis)
    gz_table(os.path.join(stenosis, "timeseries.csv.gz"), ["time_s", "centroid_x_m", "d_x", "d_y", "d_z"],
             [(x, 1e-6 * k, 1.0 + 0.01 * k, 1.0, 0.3) for k, x in enumerate(t)])
    point = {"centroid_x_m": 1e-5, "x_minus_throat_m": 0.0, "time_s": 1e-3, "d_x": 1.1}
    results = {"throat": point, "upstream": point, "downstream": point, "d_x_max_at": point, "d_x_max": 1.2,
               "height_m": 2e-5, "throat_height_m": 1e-5, "constriction_length_m": 1e-5, "reynolds": 0.1, "ca_throat": 0.5}
    with open(os.path.join(stenosis, "summary.json"), "w") as f:
        json.dump({"results": results}, f)
    return shear, migration, stenosis


def fit_folder(tmp):
    """A fit folder from the committed drag closure: its closure file, its Pareto front gzipped, a predictions table."""
    src = os.path.join(ROOT, "data", "closures", "resolved", "drag_coefficient")
    fit = os.path.join(tmp, "fit")
    os.makedirs(fit)
    shutil.copy(os.path.join(src, "cd_di_rep.toml"), fit)
    gz_copy(os.path.join(src, "pareto.csv"), os.path.join(fit, "pareto.csv.gz"))
    gz_table(os.path.join(fit, "predictions.csv.gz"), ["test", "cd", "model"],
             [(k % 5 == 0, 1000.0 + 50 * k, 1010.0 + 49 * k) for k in range(30)])
    return fit


def main():
    tools = sorted(f for f in os.listdir(TOOLS) if f.endswith(".py"))
    for name in tools:
        path = os.path.join(TOOLS, name)
        with open(path) as f:
            first = f.readline()
        check(first.startswith("#!") and os.access(path, os.X_OK), f"{name}: shebang and executable bit")
    probe = subprocess.run(interpreter() + ["-c", "import matplotlib, numpy"], capture_output=True, text=True)
    if probe.returncode != 0:
        print(f"SKIPPED: {' '.join(interpreter())} has no matplotlib/numpy (Debian: apt-get install python3-matplotlib "
              f"python3-numpy); the tools cannot draw here. {len(failures)} permission failures: {failures}")
        return SKIP if not failures else 1
    for name in tools:
        run([os.path.join(TOOLS, name), "--help"], f"{name} --help")
    drag = os.path.join(ARCHIVE, "r_star-0.2_re-0.1_setup-drag")
    lift = os.path.join(ARCHIVE, "r_star-0.2_re-0.1_setup-lift")
    for d in (drag, lift):
        check(os.path.isfile(os.path.join(d, "timeseries.csv.gz")) and not os.path.exists(os.path.join(d, "timeseries.csv")),
              f"{os.path.relpath(d, ROOT)} holds only the archived timeseries.csv.gz")
    with tempfile.TemporaryDirectory(prefix="hs_tools_") as tmp:
        t = lambda n: os.path.join(TOOLS, n)
        png(tmp, "tube_cell.png", [t("plot_tube_cell.py"), drag, os.path.join(tmp, "tube_cell.png")], "plot_tube_cell on the archive")
        tilted = os.path.join(ROOT, "data", "resolved-v2", "checks", "2026-12-07_disc_tilt", "tilt-45", "result")
        png(tmp, "disc_orientation.png", [t("plot_disc_orientation.py"), tilted, "--out", os.path.join(tmp, "disc_orientation.png")],
            "plot_disc_orientation on an archived check run")
        png(tmp, "resolution.png", [t("plot_resolution.py"), os.path.join(tmp, "resolution.png"), f"drag={drag}", f"lift={lift}"],
            "plot_resolution on two archived runs")
        dataset = gz_copy(os.path.join(ROOT, "data", "resolved", "dataset.csv"), os.path.join(tmp, "dataset.csv.gz"))
        png(tmp, "dataset.png", [t("plot_dataset.py"), dataset, os.path.join(tmp, "dataset.png")], "plot_dataset on dataset.csv.gz")
        pries = gz_copy(os.path.join(ROOT, "validate", "results", "2026-12-01_pries_checks.csv"), os.path.join(tmp, "pries.csv.gz"))
        png(tmp, "pries.png", [t("plot_pries.py"), pries, os.path.join(tmp, "pries.png")], "plot_pries on a .csv.gz")
        curves = gz_table(os.path.join(tmp, "curves.csv.gz"), ["diameter_um", "tube_hematocrit", "pries_discharge_hematocrit",
                                                                "pries_ht_d_over_ht_t", "pries_relative_apparent_viscosity"],
                          [(d, h, h * 1.3, 1.3, 1.1 + h) for h in (0.05, 0.10, 0.15) for d in (10, 30, 100, 300)])
        png(tmp, "pries_curves.png", [t("plot_pries.py"), pries, os.path.join(tmp, "pries_curves.png"), "--curves", curves,
                                      "--baseline", pries, "--baseline-label", "rigid"], "plot_pries with the law's curves and a baseline")
        stretch = gz_table(os.path.join(tmp, "stretching.csv.gz"), ["force_N", "axial_m", "transverse_m"],
                           [(f * 1e-12, (7.8 + 0.05 * f) * 1e-6, (7.8 - 0.02 * f) * 1e-6) for f in (0, 50, 100, 150)])
        band = os.path.join(ROOT, "data", "reference", "mills2004_rbc_stretch_experiment.csv")
        png(tmp, "stretching.png", [t("plot_stretching.py"), stretch, band, os.path.join(tmp, "stretching.png")],
            "plot_stretching on a .csv.gz (band: the committed .csv)")
        result = os.path.join(tmp, "tank_treading.json")
        with open(result, "w") as f:   # the shape of `validate tank-treading --json` (two settled runs a series)
            json.dump({"frequency": [{"shear_rate_experiment_1_s": g, "f_over_shear_rate": v, "settled": True}
                                     for g, v in ((8.2, 0.041), (16.9, 0.030))],
                       "frequency_viscosity_ratio_1": [{"shear_rate_experiment_1_s": 8.2, "f_over_shear_rate": 0.05,
                                                        "settled": True}],
                       "inclination": [{"eta_o_mPa_s": e, "shear_rate_experiment_1_s": g, "inclination_deg": a,
                                        "swinging_amplitude_deg": 3.0, "settled": True}
                                       for e, g, a in ((10.7, 56.2, 9.0), (104.0, 3.85, 19.0))]}, f)
        png(tmp, "tank_treading.png", [t("plot_tank_treading.py"), result, os.path.join(ROOT, "data", "reference"),
                                       os.path.join(tmp, "tank_treading.png")], "plot_tank_treading on a validation JSON")
        capsule = os.path.join(tmp, "capsule.json")
        with open(capsule, "w") as f:   # the shape of `validate capsule --json`
            json.dump({"runs": [{"ca_g": c, "taylor_deformation": d} for c, d in ((0.0375, 0.085), (0.15, 0.27))]}, f)
        png(tmp, "capsule.png", [t("plot_capsule.py"), capsule,
                                 os.path.join(ROOT, "data", "reference", "capsule_shear_taylor_deformation.csv"),
                                 os.path.join(tmp, "capsule.png")], "plot_capsule on a validation JSON")
        fit = fit_folder(tmp)
        png(tmp, "fit.png", [t("plot_fit.py"), fit, "-o", os.path.join(tmp, "fit.png")], "plot_fit on gzipped predictions and Pareto front")
        shear, migration, stenosis = plate_and_stenosis_runs(tmp)
        png(tmp, "shear.png", [t("plot_cell_flow.py"), "shear", shear, "-o", os.path.join(tmp, "shear.png")], "plot_cell_flow shear")
        png(tmp, "migration.png", [t("plot_cell_flow.py"), "migration", migration, "-o", os.path.join(tmp, "migration.png")],
            "plot_cell_flow migration")
        png(tmp, "stenosis.png", [t("plot_stenosis.py"), stenosis, os.path.join(tmp, "stenosis.png")], "plot_stenosis")
        p = run([t("hs_tables.py"), drag], "hs_tables.py on an archived run")
        check("966 rows" in p.stdout, "hs_tables.py counts the archive's 966 rows")
        out = os.path.join(tmp, "synthetic.csv")
        run([t("make_synthetic_dataset.py"), "--rows", "5", "--out", out], "make_synthetic_dataset.py writes a table")
        # The committed scaling model recomputed from its committed traffic and bench times (no MPI run): the same table.
        results = os.path.join(ROOT, "bench", "results")
        committed = os.path.join(results, "2026-12-06_cfddem_scaling_model.json")
        again = os.path.join(tmp, "scaling_model.json")
        run([t("cfddem_scaling_model.py"), "--hemoscale", "unused", "--bench-json",
             os.path.join(results, "2026-12-06_cfddem_locate.json"), "--reuse", committed, "--json", again],
            "cfddem_scaling_model.py on the committed traffic")
        with open(committed) as f, open(again) as g:
            want, got = json.load(f)["model"], json.load(g)["model"]
        check(want.keys() == got.keys() and all(abs(want[k]["s_per_cfd_step"] - got[k]["s_per_cfd_step"]) <= 1e-12 * want[k]["s_per_cfd_step"]
                                                for k in want), "cfddem_scaling_model.py reproduces the committed model")
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
