#!/usr/bin/python3
"""Sod's ideal-gas shock tube: CPU time against L1 error, ours against the
stock rhoCentralFoam, and the peer's time step (issue 18, not a test).

Runs tutorials/verification/sodIdealGas (through tests/verification/
shockTubes.py's run(): a scratch copy, setRiemannProblem, the solver,
riemannError) on --meshes cells with rhoRiemannFoam at its default (HLLC,
MUSCL, SSPRK3, maxCo 0.5) and with the stock rhoCentralFoam (Kurganov-
Tadmor, vanLeer, Euler: tests/verification/rhoCentralFoamSod) at each
--peerCo, the runs of one mesh one after the other. The CPU time is the
solver's last ExecutionTime (start-up included: the same for both; its
resolution is 0.01 s), the least of --repeats runs.

Prints per run the L1 errors of rho, u, p and the CPU time, then for each
of ours' meshes the peer's CPU time interpolated (log-log, between its two
meshes that bracket the error) at ours' L1(rho): the time to equal error.

    bench/fluid/sodTimeToError.py [--meshes 100 200 ...] [--peerCo 0.2 0.1]
        [--repeats N] [--out DIR]
"""
import argparse
import math
import os
import re
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "verification"))
import shockTubes  # noqa: E402

PEER = os.path.join(ROOT, "tests", "verification", "rhoCentralFoamSod")


def cpu(caseDir):
    """The solver's last ExecutionTime [s] in log.solver."""
    last = None
    with open(os.path.join(caseDir, "log.solver")) as f:
        for line in f:
            m = re.match(r"ExecutionTime = ([0-9.eE+-]+) s", line)
            if m:
                last = float(m.group(1))
    if last is None:
        raise RuntimeError(f"no ExecutionTime in {caseDir}/log.solver")
    return last


def interpolate(points, err):
    """CPU at error err on the log-log line through two successive meshes'
    points (error, cpu), in the order of refinement, whose errors bracket
    it (the first such pair: a peer whose error grows again on finer
    meshes is not credited with the later meshes); None if no pair does."""
    for (e0, c0), (e1, c1) in zip(points, points[1:]):
        lo, hi = min(e0, e1), max(e0, e1)
        if lo <= err <= hi and lo > 0 and hi > lo:
            w = (math.log(err) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(c0) + w*(math.log(c1) - math.log(c0)))
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--meshes", type=int, nargs="+",
                    default=[100, 200, 400, 800, 1600, 3200])
    ap.add_argument("--peerCo", type=float, nargs="+", default=[0.2, 0.1])
    ap.add_argument("--repeats", type=int, default=1,
                    help="runs per solver and mesh, the least CPU kept")
    ap.add_argument("--out", help="keep the runs here (default: a "
                    "temporary folder, removed)")
    args = ap.parse_args()
    for n in args.meshes:
        if n < 2:
            sys.exit(f"--meshes: {n} cells: need at least 2")
    if args.repeats < 1:
        sys.exit(f"--repeats: {args.repeats}: need at least 1")
    for co in args.peerCo:
        if not 0 < co <= 1:
            sys.exit(f"--peerCo: {co} is outside (0, 1]")

    tmp = None
    work = args.out
    if not work:
        tmp = tempfile.TemporaryDirectory()
        work = tmp.name
    os.makedirs(work, exist_ok=True)

    rows = {}   # label -> list of (cells, rho, u, p, cpu)
    labels = ["ours maxCo 0.5"] + [f"rhoCentralFoam maxCo {co:g}"
                                  for co in args.peerCo]
    for n in args.meshes:
        best = {}
        for k in range(args.repeats):
            sub = os.path.join(work, f"ours.{k}")
            os.makedirs(sub, exist_ok=True)
            r, _ = shockTubes.run("sodIdealGas", n, sub, [])
            d = os.path.join(sub, f"sodIdealGas_rhoRiemannFoam_{n}")
            row = (n, r["rho"], r["u"], r["p"], cpu(d))
            if labels[0] not in best or row[4] < best[labels[0]][4]:
                best[labels[0]] = row
            for co, label in zip(args.peerCo, labels[1:]):
                sub = os.path.join(work, f"co{co:g}.{k}")
                os.makedirs(sub, exist_ok=True)
                q, _ = shockTubes.run("sodIdealGas", n, sub, [],
                                      overlay=PEER, maxCo=co)
                d = os.path.join(sub, f"sodIdealGas_rhoCentralFoamSod_{n}")
                row = (n, q["rho"], q["u"], q["p"], cpu(d))
                if label not in best or row[4] < best[label][4]:
                    best[label] = row
        for label in labels:
            rows.setdefault(label, []).append(best[label])

    print("| solver | cells | L1(rho) [kg/m^3] | L1(u) [m/s] | L1(p) [Pa] "
          "| CPU [s] |")
    print("|---|---:|---:|---:|---:|---:|")
    for label in labels:
        for n, rho, u, p, c in rows[label]:
            print(f"| {label} | {n} | {rho:.4e} | {u:.4e} | {p:.4e} "
                  f"| {c:.2f} |")

    print("\nTime to equal L1(rho): the peer's CPU interpolated at ours' "
          "error (log-log between its bracketing meshes)")
    print("| ours: cells | L1(rho) [kg/m^3] | ours CPU [s] | "
          + " | ".join(f"{l} CPU [s] (ratio to ours)" for l in labels[1:])
          + " |")
    print("|---:|---:|---:|" + "---:|" * len(labels[1:]))
    for n, rho, _, _, c in rows[labels[0]]:
        cells = []
        for label in labels[1:]:
            t = interpolate([(row[1], row[4]) for row in rows[label]], rho)
            cells.append("not reached" if t is None
                         else f"{t:.2f} ({t/c:.1f}x)")
        print(f"| {n} | {rho:.4e} | {c:.2f} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
