#!/usr/bin/python3
"""The 1-um interface windows of a preview case at one solid.h5 write, from
the written element von Mises (issue 17 item 5; not a test).

    patchProfile.py CASE T [L] [INTERFACE]

At the write nearest T [ns], for the interface (default membrane-cytoplasm;
faces shared by an element of each region, as solid::InterfacePatch) and
each side: the largest window mean of the face values over an arc length L
[m] (default 1e-6) along the interface, found by a sweep of the window's
start (an independent check of the solver's exact search: the solver's
interfacePatches.dat gives it at every step, this at the write), its
centre; the window at each end of the curve (the axis, the substrate or the
other end); and the same largest with the faces weighted by their ring
area 2 pi r ds instead of ds (the physical area of the window's band in
3D), to show what the pole's weight does. Region ids in gmsh's order
(cellMesh: nucleus, cytoplasm, membrane).
"""
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi.solidResults import SolidResults

NAMES = ["nucleus", "cytoplasm", "membrane"]


def faces(conn, reg, a, b):
    """[(n0, n1, element of a, element of b)] of the shared edges"""
    ra, rb = NAMES.index(a), NAMES.index(b)
    edges = {}
    for e in range(len(conn)):
        if reg[e] not in (ra, rb):
            continue
        for k in range(4):
            n0, n1 = conn[e][k], conn[e][(k + 1) % 4]
            edges.setdefault((min(n0, n1), max(n0, n1)), {})[reg[e]] = e
    return [(n0, n1, s[ra], s[rb]) for (n0, n1), s in edges.items()
            if ra in s and rb in s]


def chain(fs):
    """The faces in order along the curve (one open curve), with the
    nodes in walking order"""
    at = {}
    for i, (n0, n1, _, _) in enumerate(fs):
        at.setdefault(n0, []).append(i)
        at.setdefault(n1, []).append(i)
    start = next(n for n, l in at.items() if len(l) == 1)
    order, nodes, used, node = [], [start], set(), start
    while True:
        nxt = [i for i in at[node] if i not in used]
        if not nxt:
            break
        i = nxt[0]
        used.add(i)
        order.append(i)
        node = fs[i][1] if fs[i][0] == node else fs[i][0]
        nodes.append(node)
    return order, nodes


def windows(b, q, w, L, n=4000):
    """Window means over [x, x + L] of q (per piece [b_i, b_i+1]) weighted
    by w per unit length, x swept over n + 1 starts: (means, starts)"""
    S = b[-1]
    xs = np.linspace(0, S - L, n + 1)

    def integral(x, f):
        i = np.clip(np.searchsorted(b, x, side="right") - 1, 0, len(q) - 1)
        P = np.concatenate([[0], np.cumsum(f*np.diff(b))])
        return P[i] + f[i]*(x - b[i])
    num = integral(xs + L, q*w) - integral(xs, q*w)
    den = integral(xs + L, w) - integral(xs, w)
    return num/den, xs


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    case, t = sys.argv[1], float(sys.argv[2])*1e-9
    L = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-6
    a, b_ = (sys.argv[4] if len(sys.argv) > 4
             else "membrane-cytoplasm").split("-")
    with SolidResults(case + "/solid/solid.h5") as f:
        X = f.mesh("coordinates")
        conn = f.mesh("connectivity")
        reg = f.mesh("region").ravel()
        k = f.nearest(t)
        vm = f.field(k, "vonMises").ravel()
        tk = f.time(k)
    fs = faces(conn, reg, a, b_)
    order, nodes = chain(fs)
    P = X[nodes][:, :2]
    ds = np.linalg.norm(np.diff(P, axis=0), axis=1)
    bb = np.concatenate([[0], np.cumsum(ds)])
    rmid = 0.5*(P[1:, 0] + P[:-1, 0])
    print("%s at the write %.2f ns: %s-%s, %d faces, %.3f um of arc from "
          "(%.2f, %.2f) to (%.2f, %.2f) um; window %g um" % (
              case, tk*1e9, a, b_, len(fs), bb[-1]*1e6, P[0, 0]*1e6,
              P[0, 1]*1e6, P[-1, 0]*1e6, P[-1, 1]*1e6, L*1e6))
    for side, r in ((2, a), (3, b_)):
        q = np.array([vm[fs[i][side]] for i in order])
        m, xs = windows(bb, q, np.ones_like(q), L)
        j = np.argmax(m)
        c = np.interp(xs[j] + L/2, bb, P[:, 0]), np.interp(xs[j] + L/2,
                                                           bb, P[:, 1])
        ma, _ = windows(bb, q, 2*np.pi*rmid, L)
        ja = np.argmax(ma)
        ca = np.interp(xs[ja] + L/2, bb, P[:, 0]), np.interp(
            xs[ja] + L/2, bb, P[:, 1])
        print("  %s side: largest arc-length mean %.2f Pa at (%.2f, %.2f) "
              "um; end windows %.2f (at (%.2f, %.2f)) and %.2f Pa (at "
              "(%.2f, %.2f)); largest ring-area mean %.2f Pa at (%.2f, "
              "%.2f) um; largest face value %.2f Pa" % (
                  r, m[j], c[0]*1e6, c[1]*1e6, m[0], P[0, 0]*1e6,
                  P[0, 1]*1e6, m[-1], P[-1, 0]*1e6, P[-1, 1]*1e6, ma[ja],
                  ca[0]*1e6, ca[1]*1e6, q.max()))


if __name__ == "__main__":
    main()
