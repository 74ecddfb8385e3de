#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The one CSV reader of the tools: reads NAME.csv or its archive NAME.csv.gz (campaign archives keep
timeseries.csv.gz), skipping '#' comment lines. Standard library only, so it imports without matplotlib.
Run alone it prints a table's columns with their first and last values:
  /usr/bin/python3 tools/hs_tables.py data/resolved/runs/r_star-0.2_re-0.1_setup-drag/timeseries.csv.gz"""
import argparse
import csv
import gzip
import io
import os


def locate(path):
    """PATH if it exists, else PATH.gz (or PATH without .gz); FileNotFoundError naming both when neither does."""
    candidates = [path, path[:-3]] if path.endswith(".gz") else [path, path + ".gz"]
    for p in candidates:
        if os.path.exists(p):
            return p
    raise FileNotFoundError(f"neither {candidates[0]} nor {candidates[1]} exists")


def run_file(run_dir, name="timeseries.csv"):
    """The file NAME of a run folder, plain or archived (.gz)."""
    return locate(os.path.join(run_dir, name))


def _text(path):
    path = locate(path)
    if path.endswith(".gz"):
        return io.TextIOWrapper(gzip.open(path, "rb"), encoding="utf-8", newline="")
    return open(path, newline="", encoding="utf-8")


def read_rows(path):
    """The rows of a CSV as dicts keyed by the header (comment lines and blank lines skipped)."""
    with _text(path) as f:
        return list(csv.DictReader(line for line in f if line.strip() and not line.startswith("#")))


def read_columns(path, names=None):
    """Columns as lists of floats: {name: [values]}, for NAMES or every column; a cell that is not a number is nan."""
    rows = read_rows(path)
    if not rows:
        return {n: [] for n in (names or [])}
    return {n: [number(r[n]) for r in rows] for n in (names or rows[0].keys())}


def read_matrix(path):
    """Header and the rows as lists of floats (for the fit's predictions.csv and pareto.csv)."""
    with _text(path) as f:
        rows = [r for r in csv.reader(line for line in f if line.strip() and not line.startswith("#")) if r]
    return rows[0], [[number(x) for x in r] for r in rows[1:]]


def number(text):
    """float(text), or nan for an empty or non-numeric cell."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("table", help="a .csv or .csv.gz file (or a run folder: its timeseries)")
    a = p.parse_args()
    path = run_file(a.table) if os.path.isdir(a.table) else locate(a.table)
    rows = read_rows(path)
    print(f"{path}: {len(rows)} rows")
    for name in (rows[0].keys() if rows else []):
        print(f"  {name}: {rows[0][name]} .. {rows[-1][name]}")


if __name__ == "__main__":
    main()
