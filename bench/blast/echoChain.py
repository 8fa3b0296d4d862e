#!/usr/bin/python3
"""The solid alone in 1D under the exact plane wave: where the substrate's
echo coming up through the cell gets its early foot (issue 17 item 1;
docs/results/blast3D.md, "What spreads the echo in the cell (branch
echo49)"); not a test.

    bench/blast/echoChain.py CASE --reference REF.npz [--out DIR]
        [--sizes 0.7e-6 0.5e-6 ...] [--variants base b2half b1zero ...]
        [--top 7.02e-6] [--point 4.108e-6] [--dt 3.7e-11] [--smear S]

CASE: a finished or prepared 3D quarter (its thermophysicalProperties,
schemes, pulse: planeWave's column, neuronFsi.planeWave.column). REF.npz:
the 1D answer at the material points of reference heights 0.10, 0.15, ...
um up to 7.9 um (the cell's top on the axis) or the top, the point and
the top (planeWave's column of the whole 100 um, 25 nm cells, to
--endTime), computed once and cached there.

For each element size H of --sizes and each variant, build/bin/echoChain
(bench/solid/echoChain.C: the quarter's hexahedra in a column, the solid
library's explicit solver) runs the column of height --top (the cell's top
above the Fig. 10 point: 7.02 um at r = 3.85 um; 7.9 um on the axis)
loaded by the 1D answer at its top's material point, and this prints, at
the point's reference height --point (the Fig. 10 point, 4.108 um):
  - the reading between the two elements whose centroids bracket the
    point (linear at the point: the quarter's interface reading), against
    the 1D answer at the point: planeWave's incident 1-ns peak error and
    the echo's foot (the first time after the arrival + 2 ns at which p
    reaches 51 MPa; neuronFsi.planeWave.crossingAfter) and its arrival
    (75 MPa), scene minus exact [ns];
  - the same reading of the exact element averages (the 1D answer
    averaged over each element's material span: what the reading would
    give if the solid were exact): the reading's own part;
  - the element containing the point against the 1D answer averaged over
    it: the solver's part.
Variants (diagnosis only; the quarter runs base):
  base      b1 0.06, b2 1.2, hourglass 0.1, filtered deviatoric
            viscosity 0.2, the step --dt (the quarter's, 3.7e-11 s)
  b2half    b2 0.6
  b1zero    b1 0
  noq       b1 0, b2 0 (no bulk viscosity)
  nodev     no deviatoric viscosity
  stable    the chain's own stable step x 0.8 (Courant 0.8 instead of the
            quarter's 0.05-0.3: the lumped mass's dispersion)
--smear S [m]: the top's load is the 1D answer's running mean over S/C
(C 1450 m/s): an incident front spread as a water mesh of about S hands
it to the cell (0: the 1D answer itself).
"""
import argparse
import os
import subprocess
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import planeWave as pw  # noqa: E402
from neuronFsi import msh, options  # noqa: E402

C0 = 1450.0
VARIANTS = {
    "base": [],
    "b2half": ["-b2", "0.6"],
    "b1zero": ["-b1", "0"],
    "noq": ["-b1", "0", "-b2", "0"],
    "nodev": ["-shearViscosity", "0"],
    "stable": None,     # no -dt: the chain's stable step
}


def reference(case, path, top, point, endTime):
    """{height: (t, p)} of the 1D answer at material points, cached in
    path (npz: z, t, p)."""
    if os.path.isfile(path):
        r = np.load(path)
        return r["z"], r["t"], r["p"]
    grid = list(np.round(np.arange(0.1e-6, max(top, 7.9e-6) + 1e-12, 0.05e-6),
                         12))
    heights = sorted(set(grid + [top, point]))
    w = pw.column(os.path.abspath(case), [], 1e-4, endTime, dz=25e-9,
                  material=heights)
    p = np.array([w.material[z]["p"] for z in heights]).T
    np.savez(path, z=np.array(heights), t=w.t, p=p)
    print("1D answer: %d material points to %.4g s, 25 nm cells -> %s"
          % (len(heights), endTime, path))
    return np.array(heights), w.t, p


def atHeight(zs, p, z):
    """The 1D answer at reference height z, linear between the material
    points (columns of p)."""
    k = int(np.clip(np.searchsorted(zs, z) - 1, 0, len(zs) - 2))
    w = (z - zs[k])/(zs[k + 1] - zs[k])
    return (1 - w)*p[:, k] + w*p[:, k + 1]


def averaged(zs, p, a, b):
    """The 1D answer averaged over the reference span [a, b] (trapezoid
    over the material points inside, the ends interpolated)."""
    z = np.concatenate(([a], zs[(zs > a) & (zs < b)], [b]))
    cols = np.array([atHeight(zs, p, x) for x in z]).T
    return np.trapz(cols, z, axis=1)/(b - a)


def columnNodes(mshPath, r):
    """The heights [m] where the vertical line x = r, y = 0 crosses from
    one element of a 3D quarter's cell mesh (cellMesh's cell.msh) to the
    next, from the substrate to the top: the scene's column of elements
    at r (its faces on the symmetry plane y = 0, quadrangles in x-z, the
    line sampled every 5 nm)."""
    X, groups = msh.read(mshPath)
    if "symmetryY" not in groups:
        raise SystemExit("echoChain.py: %s has no face group symmetryY "
                         "(not a 3D quarter's cell mesh)" % mshPath)
    quads = []
    for block in groups["symmetryY"][1]:
        tags = block[3]
        for i in range(0, len(tags), 4):
            q = np.array([X[t] for t in tags[i:i + 4]])[:, [0, 2]]
            if q[:, 0].min() <= r <= q[:, 0].max():
                quads.append(q)

    def inside(q, z):
        # the quadrangle as two triangles, (x, z) = (r, z)
        for a, b, c in ((0, 1, 2), (0, 2, 3)):
            m = np.array([q[b] - q[a], q[c] - q[a]]).T
            try:
                l1, l2 = np.linalg.solve(m, np.array([r, z]) - q[a])
            except np.linalg.LinAlgError:
                continue
            if l1 >= -1e-12 and l2 >= -1e-12 and l1 + l2 <= 1 + 1e-12:
                return True
        return False

    top = max(q[:, 1].max() for q in quads)
    nodes, current = [0.0], None
    for z in np.arange(2.5e-9, top, 5e-9):
        k = next((i for i, q in enumerate(quads) if inside(q, z)), None)
        if k is None:
            break
        if current is not None and k != current:
            nodes.append(z - 2.5e-9)
        current = k
    nodes.append(z - 2.5e-9 if k is None else top)
    return nodes


def readChain(path):
    with open(path) as f:
        head = [next(f) for _ in range(3)]
    zc = np.array([float(x) for x in head[1].split(":")[1].split()])
    d = np.loadtxt(path)
    return head[0].strip("# \n"), zc, d[:, 0], d[:, 2:]


def measure(t, p, tr, pr, z, pulse):
    s, r = pw.measures(t, p, tr, pr, 50e6, pulse, z)
    e = pw.errors(s, r)
    ta = r["arrival"]
    out = {"incident": 100*e["peakIncident"], "peak": 100*e["peak1ns"]}
    for name, level in (("foot", 51e6), ("echo", 75e6)):
        a = pw.crossingAfter(t, p, ta + 2e-9, level)
        b = pw.crossingAfter(tr, pr, ta + 2e-9, level)
        out[name] = None if a is None or b is None else (a - b)*1e9
    return out


def fmt(m):
    f = lambda x: "   -  " if x is None else "%+6.2f" % x
    return "%+6.2f %% %s ns %s ns" % (m["incident"], f(m["foot"]),
                                      f(m["echo"]))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case")
    ap.add_argument("--reference", required=True)
    ap.add_argument("--out", default=None)
    ap.add_argument("--sizes", type=float, nargs="+",
                    default=[0.7e-6, 0.5e-6, 0.35e-6, 0.25e-6, 0.175e-6])
    ap.add_argument("--variants", nargs="+", default=["base"],
                    choices=sorted(VARIANTS))
    ap.add_argument("--top", type=float, default=7.02e-6)
    ap.add_argument("--point", type=float, default=4.108e-6)
    ap.add_argument("--dt", type=float, default=3.7e-11)
    ap.add_argument("--pulse", type=float, default=1e-8)
    ap.add_argument("--smear", type=float, default=0.0)
    ap.add_argument("--endTime", type=float, default=8e-8)
    ap.add_argument("--mesh", default=None,
                    help="a 3D quarter's constant/cell.msh: the chain's "
                    "elements are the scene's along the vertical line at "
                    "x = --at, y = 0 (slivers under 0.1 um merged into a "
                    "the element above), up to --top, instead of --sizes")
    ap.add_argument("--at", type=float, default=3.852e-6)
    ap.add_argument("--maxHeight", type=float, default=0,
                    help="with --mesh: every element of the scene's column "
                    "taller than this [m] split into equal ones no taller "
                    "(what a cell mesh finer along z there would give; 0: "
                    "as the scene)")
    ap.add_argument("--positions", type=int, default=0,
                    help="also read the chain at this many points spread "
                    "evenly over one element spacing from --point up, and "
                    "print the range of the reading's errors over them")
    ap.add_argument("--chain", default=None,
                    help="the echoChain binary (default build/bin/echoChain "
                    "of this tree)")
    a = options.parse(ap)
    for name in ("top", "point", "dt", "pulse", "endTime"):
        v = getattr(a, name)
        if not (np.isfinite(v) and 0 < v < 1e-3):
            ap.error("--%s %g: not in (0, 1e-3)" % (name, v))
    if not 0 < a.point < a.top:
        ap.error("--point %g must lie inside the column (0, --top %g)"
                 % (a.point, a.top))
    if not (np.isfinite(a.maxHeight) and 0 <= a.maxHeight < a.top):
        ap.error("--maxHeight %g: not in [0, --top)" % a.maxHeight)
    if not 0 <= a.positions <= 100:
        ap.error("--positions %d: not in [0, 100]" % a.positions)
    if not (np.isfinite(a.smear) and 0 <= a.smear < 1e-5):
        ap.error("--smear %g: not in [0, 1e-5) m" % a.smear)
    for h in a.sizes:
        if not (np.isfinite(h) and 0 < h <= a.top/2):
            ap.error("--sizes %g: not in (0, --top/2]" % h)
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    chain = a.chain or os.path.join(root, "build", "bin", "echoChain")
    if not os.access(chain, os.X_OK):
        sys.exit("echoChain.py: %s not built (cmake --build build --target "
                 "echoChain)" % chain)
    out = a.out or os.path.dirname(os.path.abspath(a.reference))
    os.makedirs(out, exist_ok=True)
    zs, tr, pr = reference(a.case, a.reference, a.top, a.point, a.endTime)
    if zs[-1] < a.top*(1 - 1e-9) or zs[0] > a.point:
        sys.exit("echoChain.py: %s reaches %g m, not --top %g m: another "
                 "reference" % (a.reference, zs[-1], a.top))
    pPoint = atHeight(zs, pr, a.point)
    load = atHeight(zs, pr, a.top)
    if a.smear > 0:
        tc, mean = pw.runningMean(tr, load, a.smear/C0)
        load = np.interp(tr, tc, mean)
    ta = pw.arrival(tr, load, 50e6)
    k0 = max(0, int(np.searchsorted(tr, ta - 1e-9)))
    table = os.path.join(out, "load-%.4g-%.3g.dat" % (a.top*1e6,
                                                      a.smear*1e6))
    np.savetxt(table, np.column_stack((tr[k0:], load[k0:])),
               header="time [s], the 1D answer's pressure at the material "
               "point %g m [Pa]%s" % (a.top, " smeared over %g m" % a.smear
                                      if a.smear else ""))
    print("top %.3g um, the point %.4g um, load from %.3f ns (arrival at "
          "the top %.3f ns), smear %.3g um; reading: between the two "
          "elements bracketing the point; incident 1-ns peak error, echo's "
          "foot (51 MPa) and arrival (75 MPa) minus the 1D answer's"
          % (a.top*1e6, a.point*1e6, tr[k0]*1e9, ta*1e9, a.smear*1e6))
    print("%-8s %-7s %-4s | %-29s | %-29s | %-29s" % (
        "variant", "h [um]", "n", "reading (scene-like)",
        "reading of the exact averages", "element vs its exact average"))
    columns = []
    if a.mesh:
        nodes = [z for z in columnNodes(a.mesh, a.at) if z < a.top - 0.05e-6]
        nodes.append(a.top)
        merged = [nodes[0]]
        for z in nodes[1:-1]:
            # a sliver (the line clipping an element's corner) joins the
            # element above it
            if z - merged[-1] >= 0.1e-6:
                merged.append(z)
        if a.top - merged[-1] < 0.1e-6:
            merged.pop()
        merged.append(a.top)
        if a.maxHeight > 0:
            split = [merged[0]]
            for lo, hi in zip(merged[:-1], merged[1:]):
                k = int(np.ceil((hi - lo)/a.maxHeight - 1e-9))
                split += list(lo + (hi - lo)*np.arange(1, k + 1)/k)
            merged = split
        columns.append(("mesh" if not a.maxHeight else
                        "mesh%.3g" % (a.maxHeight*1e6), np.array(merged)))
        print("the scene's column at x = %.4g um, y = 0 (%s): %d elements, "
              "node heights [um] %s" % (a.at*1e6, a.mesh, len(merged) - 1,
                                        " ".join("%.3f" % (z*1e6)
                                                 for z in merged)))
    else:
        for H in a.sizes:
            n = max(1, int(round(a.top/H)))
            columns.append(("%.4g" % (H*1e6),
                            np.arange(n + 1)*a.top/n))
    for v in a.variants:
        for label, nodes in columns:
            res = os.path.join(out, "chain-%s-%s-%.4g-%.3g.dat"
                               % (v, label, a.top*1e6, a.smear*1e6))
            nodeFile = res[:-4] + ".nodes"
            np.savetxt(nodeFile, nodes)
            args = [chain, table, res, "-nodes", nodeFile, "-top",
                    repr(a.top)]
            args += (["-dt", repr(a.dt)] if VARIANTS[v] is not None else [])
            args += VARIANTS[v] or []
            run = subprocess.run(args, capture_output=True, text=True)
            if run.returncode != 0:
                sys.exit("echoChain.py: %s failed: %s" % (" ".join(args),
                                                          run.stderr.strip()))
            _, zc, t, p = readChain(res)
            h = np.diff(nodes).max()
            e = int(np.clip(np.searchsorted(zc, a.point) - 1, 0,
                            len(zc) - 2))
            w = (a.point - zc[e])/(zc[e + 1] - zc[e])
            reading = (1 - w)*p[:, e] + w*p[:, e + 1]
            ex = [averaged(zs, pr, lo, hi)
                  for lo, hi in zip(nodes[:-1], nodes[1:])]
            exReading = (1 - w)*ex[e] + w*ex[e + 1]
            host = int(np.clip(np.searchsorted(nodes, a.point) - 1, 0,
                               len(zc) - 1))
            print("%-8s %-7s %-4d | %s | %s | %s" % (
                v, label, len(zc),
                fmt(measure(t, reading, tr, pPoint, a.point, a.pulse)),
                fmt(measure(tr, exReading, tr, pPoint, a.point, a.pulse)),
                fmt(measure(t, p[:, host], tr, ex[host], zc[host],
                            a.pulse))))
            if a.positions:
                got = []
                for j in range(a.positions):
                    z = a.point + j*(zc[1] - zc[0])/a.positions
                    e = int(np.clip(np.searchsorted(zc, z) - 1, 0,
                                    len(zc) - 2))
                    w = (z - zc[e])/(zc[e + 1] - zc[e])
                    pz = atHeight(zs, pr, z)
                    got.append((w, measure(t, (1 - w)*p[:, e]
                                           + w*p[:, e + 1], tr, pz, z,
                                           a.pulse),
                                measure(tr, (1 - w)*ex[e] + w*ex[e + 1],
                                        tr, pz, z, a.pulse)))
                print("%-8s %-7s      | the point at %d positions over "
                      "one spacing (weight of the upper element %.2f to "
                      "%.2f): incident %+.2f to %+.2f %%, foot %+.2f to "
                      "%+.2f ns; on the exact averages %+.2f to %+.2f %%, "
                      "%+.2f to %+.2f ns" % (
                          v, label, a.positions, min(g[0] for g in got),
                          max(g[0] for g in got),
                          min(g[1]["incident"] for g in got),
                          max(g[1]["incident"] for g in got),
                          min(g[1]["foot"] for g in got),
                          max(g[1]["foot"] for g in got),
                          min(g[2]["incident"] for g in got),
                          max(g[2]["incident"] for g in got),
                          min(g[2]["foot"] for g in got),
                          max(g[2]["foot"] for g in got)))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
