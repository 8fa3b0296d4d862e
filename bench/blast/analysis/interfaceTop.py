#!/usr/bin/python3
"""Which elements make an interface maximum of a preview case (issue 17
item 5; not a test).

    interfaceTop.py CASE T0 [N]

For each write of CASE/solid/solid.h5 from T0 [ns] on: per region
interface of constant/solidProperties' `interfaces` (the elements of
either region with a node on the other, as solidDomain's
postProcessing/solidInterfaces), the N (default 3) largest element von
Mises: region, centroid (r, z) [um], von Mises [Pa], J, the element's
size (square root of its r-z area) [um], and the mean von Mises of the
band's elements of each side [Pa]. Region ids in gmsh's order of the 2D
physical groups (cellMesh: nucleus, cytoplasm, membrane).
"""
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi.solidResults import SolidResults

NAMES = ["nucleus", "cytoplasm", "membrane"]


def band(conn, reg, a, b):
    ra, rb = NAMES.index(a), NAMES.index(b)
    inA = np.zeros(conn.max() + 1, bool)
    inB = np.zeros_like(inA)
    inA[conn[reg == ra].ravel()] = True
    inB[conn[reg == rb].ravel()] = True
    return np.array([e for e in range(len(conn))
                     if (reg[e] == ra and inB[conn[e]].any())
                     or (reg[e] == rb and inA[conn[e]].any())])


def quadAreas(X, conn):
    """The areas [m^2] of the r-z quadrilaterals conn (node rows of X,
    r and z first), by the shoelace formula."""
    x, y = X[conn][:, :, 0], X[conn][:, :, 1]
    return 0.5*np.abs(np.sum(x*np.roll(y, -1, 1) - np.roll(x, -1, 1)*y,
                             axis=1))


def patchMaximum(C, reg, els, vm, radius):
    """The largest, over the band elements els, of the mean von Mises of
    the band elements of the same region whose centroids C lie within
    radius [m] of its centroid (a mean over a fixed length of the
    interface instead of one element), and the element it is centred on."""
    best, at = -1.0, -1
    for e in els:
        near = els[(reg[els] == reg[e])
                   & (np.linalg.norm(C[els] - C[e], axis=1) <= radius)]
        v = vm[near].mean()
        if v > best:
            best, at = v, e
    return best, at


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    case, t0 = sys.argv[1], float(sys.argv[2])
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    with SolidResults(case + "/solid/solid.h5") as f:
        X = f.mesh("coordinates")
        conn = f.mesh("connectivity")
        reg = f.mesh("region").ravel()
        C = X[conn].mean(axis=1)
        area = quadAreas(X, conn)
        size = np.sqrt(area)
        pairs = [("membrane", "cytoplasm"), ("cytoplasm", "nucleus")]
        bands = {p: band(conn, reg, *p) for p in pairs}
        for s in f.steps():
            t = f.time(s)*1e9
            if t < t0:
                continue
            vm = f.field(s, "vonMises").ravel()
            J = f.field(s, "J").ravel()
            for p, els in bands.items():
                k = els[np.argsort(-vm[els])[:n]]
                means = " / ".join(
                    "%s %.2f" % (r[:4], vm[els[reg[els] == NAMES.index(r)]]
                                 .mean()) for r in p)
                print("%7.2f ns %s-%s (%d el; mean %s Pa): " % (
                    t, p[0][:4], p[1][:4], len(els), means) + " | ".join(
                    "%s (%.2f,%.2f) vM %.2f J %.4f h %.2f" % (
                        NAMES[reg[e]][:4], C[e, 0]*1e6, C[e, 1]*1e6, vm[e],
                        J[e], size[e]*1e6) for e in k))


if __name__ == "__main__":
    main()
