#!/usr/bin/python3
"""The bytes per cell of rhoRiemannFoam item by item (issue 18: <= 1 KB).

What the solver holds at its peak (inside an SSPRK3 stage) on the 3D boxes
of bench/fluid/memoryPerCell.py, from the sizes of the data: 8 B per scalar,
24 per vector, 72 per tensor, 4 per label; an n^3 box has n^3 cells,
3 n^2 (n - 1) internal faces, 6 n^2 boundary faces and (n + 1)^3 points.
OpenFOAM's face list holds per face a list header (16 B) and a heap block
of 4 labels (16 B, a 32 B chunk of glibc's malloc). Each item's slope over
the same boxes (least squares, as memoryPerCell.py fits peak RSS) is its
bytes per cell; their sum is compared with the measured slope there. The
allocation sites and sizes were confirmed with heaptrack on the 60^3 box
(docs/benchmarks/fluid.md, "Memory per cell").

    bench/fluid/memoryLedger.py [--sizes "40 60 80 100"]

Prints a markdown table: item, bytes per cell before (main up to d349cf6)
and now. Not a test.
"""
import argparse

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import bench

# item: (bytes per cell, per internal face, per boundary face, per point),
# where it lives
ITEMS = [
    ("points", (0, 0, 0, 24), "polyMesh"),
    ("faces (list header 16 B + 32 B heap chunk of 4 labels)",
     (0, 48, 48, 0), "polyMesh"),
    ("owner, neighbour", (0, 8, 4, 0), "polyMesh"),
    ("face centres and areas (Sf)", (0, 48, 48, 0), "primitiveMesh"),
    ("cell centres and volumes", (32, 0, 0, 0), "primitiveMesh"),
    ("magSf, weights", (0, 16, 16, 0), "fvMesh"),
    ("p, T, rho, e, c", (40, 0, 40, 0), "rhoEThermo"),
    ("U, rhoU, rhoE", (56, 0, 56, 0), "conservativeFluid"),
    ("state at the start of the step rho0, rhoU0, rhoE0, V0",
     (48, 0, 0, 0), "conservativeFluid (SSPRK3's q(0))"),
    ("face fluxes phi, phiU, phiE, amaxSf", (0, 48, 48, 0),
     "conservativeFluid"),
    ("cell gradients of rho, U, p", (120, 0, 120, 0), "MUSCLReconstruction"),
    ("flux divergences divPhi, divPhiU, divPhiE", (40, 0, 0, 0),
     "conservativeFluid::step"),
]
# Items of the solver before: (bytes per ..., where), now gone
BEFORE_ONLY = [
    ("face states of both sides (rho, U, p, e, c) of every internal face",
     (0, 112, 0, 0), "riemannFlux L_, R_ (now one block of 1,024 faces)"),
    ("temporaries of the stage update's field expressions",
     (48, 0, 0, 0), "conservativeFluid::step (now cell by cell)"),
]


def slope(coeffs, sizes):
    cells, total = [], []
    for n in sizes:
        counts = (n**3, 3*n*n*(n - 1), 6*n*n, (n + 1)**3)
        cells.append(n**3)
        total.append(sum(c*k for c, k in zip(coeffs, counts)))
    return np.polyfit(np.array(cells, float), np.array(total, float), 1)[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default="40 60 80 100",
                    help="cells per edge of the boxes")
    sizes = [int(s) for s in bench.parse(ap).sizes.split()]
    print("| item | where | before [B/cell] | now [B/cell] |")
    print("|---|---|---:|---:|")
    before = now = 0.0
    for name, coeffs, where in ITEMS:
        b = slope(coeffs, sizes)
        before += b
        now += b
        print(f"| {name} | {where} | {b:.1f} | {b:.1f} |")
    for name, coeffs, where in BEFORE_ONLY:
        b = slope(coeffs, sizes)
        before += b
        print(f"| {name} | {where} | {b:.1f} | 0 |")
    print(f"| **sum** | | **{before:.0f}** | **{now:.0f}** |")


if __name__ == "__main__":
    bench.main(main)
