#!/usr/bin/python3
"""Verification of rhoRiemannFoam against exact Riemann solutions.

Runs a shock-tube tutorial of tutorials/verification on a sequence of meshes
(in a scratch copy, the tutorial itself is untouched), reads the errors that
riemannError writes and asserts:
  - the run reaches its end time (the solver stops on any invalid state);
  - the star state (pressure at the contact, densities beside it) within
    --star-tol of the exact one on the finest mesh;
  - the observed order of the L1 error of each quantity between successive
    meshes, averaged over the sequence, at least the given minimum
    (--order rho=0.6 p=0.85 ..., 'Smooth' suffix: away from the wave edges).
Prints a table: cells, L1 errors, star-state errors, wall time.
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import postProcessing, scratch

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TUTORIALS = os.path.join(ROOT, "tutorials", "verification")
COLUMNS = ["nCells", "rho", "u", "p", "pStar", "rhoStarL", "rhoStarR",
           "rhoSmooth", "pSmooth"]


def foam(cmd, cwd):
    """Run a shell command in the project environment; raise on failure."""
    full = f". '{ROOT}/etc/bashrc' && {cmd}"
    res = subprocess.run(["bash", "-c", full], cwd=cwd,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True)
    if res.returncode != 0:
        sys.stdout.write(res.stdout[-3000:])
        log = os.path.join(cwd, "log.solver")
        if os.path.exists(log):
            sys.stdout.write(open(log).read()[-3000:])
        raise RuntimeError(f"'{cmd}' failed in {cwd} (exit {res.returncode})")
    return res.stdout


def run(case, nCells, work, overrides, overlay=None, maxCo=None):
    """Run the case on nCells cells, with the files of the directory overlay
    copied over it (another solver); return (errors dict, wall time [s])."""
    tag = os.path.basename(overlay) if overlay else "rhoRiemannFoam"
    dst = os.path.join(work, f"{case}_{tag}_{nCells}")
    scratch.copyInputs(os.path.join(TUTORIALS, case), dst,
                       ("0.orig", "system", "constant"), ("polyMesh",))
    if overlay:
        shutil.copytree(overlay, dst, dirs_exist_ok=True)
    app = "rhoCentralFoam" if overlay else "rhoRiemannFoam"
    foam(f"sed -i 's/^application .*/application {app};/' system/controlDict",
         dst)
    if maxCo:
        foam(f"sed -i 's/^maxCo .*/maxCo {maxCo};/' system/controlDict", dst)
    # foamDictionary would expand the $variables: edit the one line
    foam(f"sed -i 's/^nCells .*/nCells {nCells};/' system/blockMeshDict", dst)
    for entry, value in overrides:
        dictFile, key = entry.split(":")
        foam(f"foamDictionary -entry '{key}' -set '{value}' {dictFile}"
             " > /dev/null", dst)
    foam("rm -rf 0 && cp -r 0.orig 0 && blockMesh > log.blockMesh"
         " && setRiemannProblem > log.set", dst)
    start = time.perf_counter()
    foam(f"{app} > log.solver", dst)
    wall = time.perf_counter() - start
    foam("riemannError -latestTime > log.error", dst)
    values = postProcessing.latest(dst, "riemannError/errors.dat").data()[0]
    return dict(zip(COLUMNS, values)), wall


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--meshes", type=int, nargs="+",
                    default=[100, 200, 400, 800])
    ap.add_argument("--order", nargs="*", default=[],
                    help="quantity=minimum mean observed order")
    ap.add_argument("--star-tol", type=float, default=0.01)
    ap.add_argument("--compare", metavar="OVERLAY",
                    help="also run the stock rhoCentralFoam with this case"
                         " overlay (at --peer-co) and require our L1 errors"
                         " of rho, u, p to be no larger on every mesh")
    ap.add_argument("--peer-co", type=float, default=0.1,
                    help="the peer's maxCo (default 0.1: at its tutorial's"
                         " 0.2 its Euler step grows a post-shock oscillation"
                         " and its error grows again beyond 800 cells;"
                         " bench/fluid/sodTimeToError.py)")
    ap.add_argument("--set", nargs="*", default=[], metavar="FILE:KEY=VALUE",
                    help="dictionary overrides, e.g. "
                         "system/fvSolution:riemann/riemannSolver=HLL")
    args = ap.parse_args()
    if not 0 < args.peer_co <= 1:
        ap.error(f"--peer-co {args.peer_co}: outside (0, 1]")
    overrides = [tuple(s.split("=", 1)) for s in args.set]

    rows = []
    peer = []
    with tempfile.TemporaryDirectory() as work:
        for n in args.meshes:
            rows.append(run(args.case, n, work, overrides))
            if args.compare:
                peer.append(run(args.case, n, work, [],
                                overlay=os.path.abspath(args.compare),
                                maxCo=args.peer_co))

    print(f"{args.case}: L1 errors against the exact solution")
    print(f"{'cells':>6} {'rho[kg/m3]':>11} {'u[m/s]':>10} {'p[Pa]':>11}"
          f" {'rhoSm[kg/m3]':>12} {'pSm[Pa]':>10} {'p* err':>9}"
          f" {'rho*L err':>9} {'rho*R err':>9} {'wall[s]':>8}")
    for r, wall in rows:
        print(f"{int(r['nCells']):6d} {r['rho']:11.4e} {r['u']:10.4e}"
              f" {r['p']:11.4e} {r['rhoSmooth']:12.4e} {r['pSmooth']:10.4e}"
              f" {r['pStar']:9.2e} {r['rhoStarL']:9.2e} {r['rhoStarR']:9.2e}"
              f" {wall:8.2f}")

    failures = []
    if peer:
        print(f"\nstock rhoCentralFoam (Kurganov-Tadmor, maxCo"
              f" {args.peer_co:g}), same meshes:")
        print(f"{'cells':>6} {'rho[kg/m3]':>11} {'u[m/s]':>10}"
              f" {'p[Pa]':>11} {'wall[s]':>8}   ours/theirs: rho u p")
        for (r, wall), (q, qwall) in zip(rows, peer):
            ratios = [r[k]/q[k] for k in ("rho", "u", "p")]
            print(f"{int(q['nCells']):6d} {q['rho']:11.4e} {q['u']:10.4e}"
                  f" {q['p']:11.4e} {qwall:8.2f}   "
                  + " ".join(f"{x:.3f}" for x in ratios))
            for k, x in zip(("rho", "u", "p"), ratios):
                if not x <= 1:
                    failures.append(f"L1({k}) on {int(r['nCells'])} cells is"
                                    f" {x:.3f} x that of rhoCentralFoam")
    finest = rows[-1][0]
    for key in ("pStar", "rhoStarL", "rhoStarR"):
        if not finest[key] <= args.star_tol:
            failures.append(f"{key} relative error {finest[key]:.3e} >"
                            f" {args.star_tol} on {int(finest['nCells'])}"
                            " cells")
    for spec in args.order:
        name, minimum = spec.split("=")
        key = name.replace("Smooth", "") + ("Smooth" if "Smooth" in name
                                            else "")
        orders = []
        for (a, _), (b, _) in zip(rows[:-1], rows[1:]):
            orders.append(math.log(a[key]/b[key])
                          / math.log(b["nCells"]/a["nCells"]))
        mean = sum(orders)/len(orders)
        print(f"observed order of L1({name}): "
              + " ".join(f"{o:.2f}" for o in orders) + f", mean {mean:.2f}"
              f" (required >= {minimum})")
        if not mean >= float(minimum):
            failures.append(f"order of L1({name}) {mean:.2f} < {minimum}")

    if failures:
        print("FAILED: " + "; ".join(failures))
        return 1
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
