#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# Copies what the repository keeps of each finished campaign run: summary.json and timeseries.csv thinned to at most
# MAX_ROWS rows (every k-th sample, the last one always kept), gzip-compressed, under data/resolved/runs/<run>/.
# The full outputs stay in the (git-ignored) campaign folder. Also prints the campaign's CPU hours so far and the wall
# hours its runs/invocations.json recorded.
# Usage: /usr/bin/python3 tools/archive_campaign.py cases/campaign/tube-re-rstar data/resolved/runs
import gzip
import json
import os
import shutil
import sys

MAX_ROWS = 1000


def thin(lines):
    header, rows = lines[0], lines[1:]
    step = max(1, -(-len(rows) // MAX_ROWS))
    kept = rows[::step]
    if rows and kept[-1] is not rows[-1]:
        kept.append(rows[-1])
    return [header] + kept


def main():
    campaign, archive = sys.argv[1], sys.argv[2]
    runs = os.path.join(campaign, "runs")
    wall = done = 0
    for name in sorted(os.listdir(runs)):
        status_file = os.path.join(runs, name, "status.json")
        if not os.path.exists(status_file):
            continue
        with open(status_file) as f:
            status = json.load(f)
        wall += status.get("wall_s", 0.0)
        if status.get("state") != "done":
            continue
        done += 1
        out = os.path.join(runs, name, "output")
        dest = os.path.join(archive, name)
        os.makedirs(dest, exist_ok=True)
        shutil.copyfile(os.path.join(out, "summary.json"), os.path.join(dest, "summary.json"))
        with open(os.path.join(out, "timeseries.csv")) as f:
            lines = f.readlines()
        # mtime=0: the same series gives the same bytes, so re-archiving leaves committed runs unchanged.
        with open(os.path.join(dest, "timeseries.csv.gz"), "wb") as raw:
            with gzip.GzipFile(fileobj=raw, mode="wb", mtime=0) as z:
                z.write("".join(thin(lines)).encode())
    # One thread per run: CPU hours = the runs' wall hours (failed and retried attempts included).
    print(f"{done} runs archived in {archive}; {wall / 3600:.2f} CPU hours of finished or failed runs so far")
    invocations = os.path.join(runs, "invocations.json")
    if os.path.exists(invocations):
        with open(invocations) as f:
            entries = json.load(f)
        hours = sum(e.get("wall_s", 0.0) for e in entries) / 3600
        print(f"campaign wall time recorded in {invocations}: {hours:.2f} h over {len(entries)} invocations")


if __name__ == "__main__":
    main()
