#!/usr/bin/python3
"""Marginal memory of rhoRiemannFoam per cell (issue 18: <= 1 KB per cell).

The peak resident memory of a run includes the libraries and start-up
(tens of MB), so RSS / cells overstates the cost of a cell on small meshes
and the difference to an unrelated run (a 1D mesh) mixes in what differs
between the two set-ups. Here the same 3D Sod case (bench/fluid/run.py's
sod_case: HLLC, MUSCL, SSPRK3, fixed deltaT) runs on n^3 boxes for a few
steps and the slope of peak RSS against cells (least squares over the
sizes) is the memory a cell costs; the intercept is the fixed part.

    bench/fluid/memoryPerCell.py [--out DIR] [--sizes "40 60 80 100"]
                                 [--steps 3]

Prints a markdown table (cells, peak RSS [MB], RSS per cell [KB]) and the
fit. Not a test.
"""
import argparse
import importlib.util
import os

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import bench

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location(
    "fluidBench", os.path.join(HERE, "run.py"))
fluidBench = importlib.util.module_from_spec(spec)
spec.loader.exec_module(fluidBench)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(HERE, "output", "memory"))
    ap.add_argument("--sizes", default="40 60 80 100",
                    help="cells per edge of the boxes")
    ap.add_argument("--steps", type=int, default=3)
    args = bench.parse(ap)
    sizes = [int(s) for s in args.sizes.split()]
    if len(sizes) < 2 or min(sizes) < 2 or args.steps < 1:
        ap.error("--sizes: at least two boxes of 2 or more cells per edge; "
                 "--steps >= 1")
    os.makedirs(args.out, exist_ok=True)
    cells, rss = [], []
    for n in sizes:
        case = os.path.join(args.out, f"box{n}")
        # run.py's copy_tutorial empties only a box of its own earlier
        # output, never a user's folder (neuronFsi.scratch.outputFolder)
        cells.append(fluidBench.sod_case(case, n, 3, args.steps))
        rss.append(fluidBench.run_solver(case, "rhoRiemannFoam")["rss"][0])
        print(f"{cells[-1]} cells: peak RSS {rss[-1]:.1f} MB", flush=True)
    slope, icpt = np.polyfit(np.array(cells, float), np.array(rss), 1)
    print("| cells | peak RSS [MB] | RSS per cell [KB] |")
    print("|---:|---:|---:|")
    for c, r in zip(cells, rss):
        print(f"| {c} | {r:.1f} | {r*1024/c:.3f} |")
    fit = icpt + slope*np.array(cells, float)
    print(f"least-squares fit: {slope*1024*1024:.0f} B per cell "
          f"({slope*1024:.3f} KB per cell), fixed part {icpt:.1f} MB; "
          f"largest residual {np.abs(fit - np.array(rss)).max():.1f} MB")


if __name__ == "__main__":
    bench.main(main)
