#!/usr/bin/env python3
"""The CFD-DEM step on 32-256 MPI ranks, modelled from what `hemoscale bench cfddem` does on this machine (issue #28).

Measured here, per CFD step of the bench's periodic 100 um tube (z-slabs, one per rank, one thread each):
  * the messages and bytes each rank sends, point to point and inside collectives (Open MPI's monitoring component,
    `--mca pml_monitoring_enable 1`), from two runs with different numbers of timed steps, so the set-up and the
    warm-up step difference away;
  * the step's time on one rank at 1e4, 1e5 and 1e6 RBCs (the "_np1" keys of a bench JSON).
Modelled on paper: T(P) = T_1(N / P) + T_p2p + T_coll, with T_1 the one-rank time of the rank's share (log-log
interpolated between the measured sizes), T_p2p = m (alpha + b / (m beta)) from the busiest rank's messages m and bytes
b, and T_coll = c ceil(log2 P) alpha for c collective calls of a few bytes each (recursive doubling). alpha and beta are
a cluster's, not this machine's: defaults 1.5 us and 12.5 GB/s (100 Gb/s InfiniBand, MPI latency of a few us), flags.

Usage: tools/cfddem_scaling_model.py --hemoscale build/app/hemoscale --bench-json bench/results/X.json
       [--size 100000] [--ranks 2 4 8] [--steps 3 13] [--json OUT] [--reuse EARLIER_OUT]
"""
import argparse
import glob
import json
import math
import os
import re
import subprocess
import sys
import tempfile

E_LINE = re.compile(r"^E\t(\d+)\t(\d+)\t(\d+) bytes\t(\d+) msgs sent")
C_LINE = re.compile(r"^C\t(\d+)\t(\d+)\t(\d+) bytes\t(\d+) msgs sent")
A2A_LINE = re.compile(r"^(O2A|A2O|A2A)\t(\d+)\t(\d+) bytes\t(\d+) msgs sent")


def read_rank(path):
    """One rank's monitoring file: point-to-point msgs/bytes per peer (self excluded), collective-generated ones, and
    the msgs this rank sent inside collectives (all communicators)."""
    p2p, coll, inside = {}, {}, 0
    with open(path) as f:
        for line in f:
            if m := E_LINE.match(line):
                src, dst, nbytes, msgs = map(int, m.groups())
                if src != dst:
                    p2p[dst] = (msgs, nbytes)
            elif m := C_LINE.match(line):
                src, dst, nbytes, msgs = map(int, m.groups())
                coll[dst] = (msgs, nbytes)
            elif m := A2A_LINE.match(line):
                inside += int(m.group(4))
    return p2p, coll, inside


def measure(hemoscale, ranks, size, steps, folder):
    prefix = os.path.join(folder, f"np{ranks}_n{size}_s{steps}")
    env = dict(os.environ, HS_BENCH_CFDDEM_SCALING_JOB="1", HS_BENCH_CFDDEM_SIZES=str(size),
               HS_BENCH_CFDDEM_TIMED_STEPS=str(steps), OMP_NUM_THREADS="1")
    cmd = ["mpiexec", "-n", str(ranks), "--oversubscribe"]
    if os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    cmd += ["--mca", "pml_monitoring_enable", "1", "--mca", "pml_monitoring_enable_output", "3",
            "--mca", "pml_monitoring_filename", prefix, hemoscale, "bench", "cfddem", "--json", prefix + ".json"]
    subprocess.run(cmd, env=env, check=True, stdout=subprocess.DEVNULL)
    with open(prefix + ".json") as f:
        substeps = json.load(f)[f"cfddem_{size_key(size)}_dem_steps_per_cfd_step_np{ranks}"]
    files = sorted(glob.glob(prefix + ".*.prof"), key=lambda p: int(p.split(".")[-2]))
    if len(files) != ranks:
        sys.exit(f"{prefix}: {len(files)} monitoring files for {ranks} ranks (is Open MPI's monitoring component there?)")
    return [read_rank(p) for p in files], substeps


def size_key(n):
    e = int(round(math.log10(n)))
    return f"1e{e}" if 10 ** e == n else f"{n / 10 ** e:g}e{e}".replace(".", "")


def per_step(lo, hi, steps):
    """Per CFD step, one dict per rank: point-to-point msgs, bytes and peers; the msgs and bytes collectives generated;
    the collective operations (msgs_inside_collectives: the monitoring's per-communicator count)."""
    d = steps[1] - steps[0]
    out = []
    for (p_lo, c_lo, i_lo), (p_hi, c_hi, i_hi) in zip(lo, hi):
        def diff(a, b, k):
            return sum(v[k] for v in b.values()) - sum(v[k] for v in a.values())
        peers = sum(1 for q in p_hi if p_hi[q][0] - p_lo.get(q, (0, 0))[0] > 0)
        out.append({"p2p_msgs": diff(p_lo, p_hi, 0) / d, "p2p_bytes": diff(p_lo, p_hi, 1) / d, "p2p_peers": peers,
                    "coll_msgs": diff(c_lo, c_hi, 0) / d, "coll_bytes": diff(c_lo, c_hi, 1) / d,
                    "msgs_inside_collectives": (i_hi - i_lo) / d})
    return out


def one_rank_time(bench, n):
    """The bench's one-rank, one-thread s per CFD step at n RBCs, log-log interpolated (extrapolated past the ends
    with the nearest segment's slope)."""
    pts = sorted((10.0 ** int(m.group(1)), v) for k, v in bench.items()
                 if (m := re.fullmatch(r"cfddem_1e(\d)_s_per_cfd_step_np1", k)))
    if len(pts) < 2:
        sys.exit("the bench JSON needs cfddem_1eX_s_per_cfd_step_np1 for at least two sizes")
    i = 0
    while i + 2 < len(pts) and n > pts[i + 1][0]:
        i += 1
    (n0, t0), (n1, t1) = pts[i], pts[i + 1]
    slope = math.log(t1 / t0) / math.log(n1 / n0)
    return t0 * (n / n0) ** slope


def log2_fit(points):
    """(a, b) of y = a + b log2 P through [(P, y)] by least squares; b = 0 with one point."""
    if len(points) == 1:
        return points[0][1], 0.0
    xs = [math.log2(p) for p, _ in points]
    ys = [y for _, y in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return my - b * mx, b


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hemoscale", default="build/app/hemoscale", help="the executable to measure (not with --reuse)")
    ap.add_argument("--bench-json", required=True, help="a `bench cfddem --json` file with the _np1 keys")
    ap.add_argument("--size", type=int, default=100000, help="RBCs in the measured runs")
    ap.add_argument("--ranks", type=int, nargs="+", default=[2, 4, 8])
    ap.add_argument("--steps", type=int, nargs=2, default=[3, 13], help="timed steps of the two runs")
    ap.add_argument("--model-size", type=int, default=1000000, help="RBCs of the modelled job")
    ap.add_argument("--model-ranks", type=int, nargs="+", default=[32, 64, 128, 256])
    ap.add_argument("--alpha-us", type=float, default=1.5, help="MPI latency between nodes, us")
    ap.add_argument("--beta-GB-s", type=float, default=12.5, help="link bandwidth, GB/s")
    ap.add_argument("--json", help="write the measurements and the model here")
    ap.add_argument("--reuse", help="take the measured traffic from this earlier --json instead of running")
    a = ap.parse_args()
    with open(a.bench_json) as f:
        bench = json.load(f)
    result = {"size": a.size, "steps": a.steps, "measured": {}, "model": {}}
    if a.reuse:
        with open(a.reuse) as f:
            old = json.load(f)
        result.update(size=old["size"], steps=old["steps"], measured=old["measured"])
        a.ranks = []
    with tempfile.TemporaryDirectory() as folder:
        for p in a.ranks:
            lo, s_lo = measure(a.hemoscale, p, a.size, a.steps[0], folder)
            hi, s_hi = measure(a.hemoscale, p, a.size, a.steps[1], folder)
            ranks = per_step(lo, hi, a.steps)
            busiest = max(ranks, key=lambda r: r["p2p_msgs"] + r["coll_msgs"])
            result["measured"][f"np{p}"] = {"per_rank": ranks, "busiest": busiest,
                                           "dem_steps_per_cfd_step": [s_lo, s_hi]}
            print(f"np {p}: per CFD step, the busiest rank sends {busiest['p2p_msgs']:.0f} point-to-point msgs "
                  f"({busiest['p2p_bytes'] / 1e3:.1f} kB) to {busiest['p2p_peers']} peers, takes part in "
                  f"{busiest['msgs_inside_collectives']:.0f} collective operations and sends {busiest['coll_msgs']:.0f} "
                  f"msgs ({busiest['coll_bytes'] / 1e3:.2f} kB) inside them (this node's algorithms: to every rank)")
    # Collective operations per step and rank (the monitoring's per-communicator count): the largest measured. On a
    # cluster a small allreduce takes ~log2 P message rounds (recursive doubling), whatever one node's MPI chose here.
    calls = max(v["busiest"]["msgs_inside_collectives"] for v in result["measured"].values())
    # Point-to-point traffic of the busiest rank, measured on >= 4 ranks (slabs with two distinct neighbours; on two the
    # neighbours coincide), grows with P (BoomerAMG's coarse levels reach past the neighbours): fitted as a + b log2 P
    # (least squares; constant with one such P) and extrapolated.
    wide = sorted((int(k[2:]), v["busiest"]) for k, v in result["measured"].items() if int(k[2:]) >= 4)
    if not wide:
        sys.exit("--ranks must include a count >= 4 (two distinct neighbours per slab)")
    fits = {q: log2_fit([(p, w[q]) for p, w in wide]) for q in ("p2p_msgs", "p2p_bytes", "p2p_peers")}
    result["p2p_fit_a_plus_b_log2P"] = fits
    alpha, beta = a.alpha_us * 1e-6, a.beta_GB_s * 1e9
    t1 = one_rank_time(bench, a.model_size)
    print(f"model: {a.model_size} RBCs, one rank {t1:.2f} s per CFD step; per step and rank {calls:.0f} collective calls "
          f"and point to point a + b log2 P: msgs {fits['p2p_msgs'][0]:.0f} + {fits['p2p_msgs'][1]:.0f}, "
          f"kB {fits['p2p_bytes'][0] / 1e3:.1f} + {fits['p2p_bytes'][1] / 1e3:.1f}; alpha {a.alpha_us} us, beta {a.beta_GB_s} GB/s")
    for p in a.model_ranks:
        comp = one_rank_time(bench, a.model_size / p)
        m = fits["p2p_msgs"][0] + fits["p2p_msgs"][1] * math.log2(p)
        b = fits["p2p_bytes"][0] + fits["p2p_bytes"][1] * math.log2(p)
        p2p = m * alpha + b / beta
        coll = calls * math.ceil(math.log2(p)) * alpha
        total = comp + p2p + coll
        eff = t1 / (p * total)
        result["model"][f"np{p}"] = {"p2p_msgs": m, "p2p_bytes": b, "compute_s": comp, "p2p_s": p2p,
                                      "collectives_s": coll, "s_per_cfd_step": total, "strong_efficiency": eff,
                                      "communication_efficiency": comp / total}
        print(f"  {p:4d} ranks: {total * 1e3:7.1f} ms per CFD step = compute {comp * 1e3:6.1f} + point to point "
              f"{p2p * 1e3:5.2f} + collectives {coll * 1e3:5.2f}; strong-scaling efficiency {eff:.2f} (vs one rank at "
              f"{a.model_size}), compute share {comp / total:.2f}")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(result, f, indent=2)


if __name__ == "__main__":
    main()
