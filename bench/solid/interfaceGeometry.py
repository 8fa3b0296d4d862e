#!/usr/bin/python3
"""Where the Fig. 10 point sits on each mesh of a ladder, relative to the
discrete nucleus surface and its elements (issue 17 item 4; docs/results/
blastPlaneWave.md, "A map smooth across the nucleus surface"; not a test).

Usage: interfaceGeometry.py [-solidProperties FILE] H=CELL.msh [H=...]

The point is placed as the coupled solver places it (bench/solid/
cellProbes.py): on the cytoplasm-nucleus interface edge crossing the
height heightFraction of the nucleus, so it lies on the polygon of the
nucleus surface at every level by construction (distance 0 to the discrete
interface). Per mesh it prints, lengths in nm:

  r            the point's radius [um]
  sag          its distance inside the exact ellipse (the chord's sag,
               along the ellipse's normal)
  edge, t      the interface edge's length and the point's place on it
               (0, 1: at a node; 0.5: mid-edge)
  thick c / n  the height of the cytoplasm (nucleus) element on that edge,
               normal to the edge: the distance of its far nodes' mean
               from the edge's line
  patch        the recovery patch's cytoplasm elements (the containing
               element and those sharing a node with it, solid::
               PointProbe): their count, and the distance from the edge's
               line of their centroids: mean and largest (the point is
               extrapolated from the centroids' mean to 0)
  angle        the kink of the node lines crossing the interface at the
               edge's nodes: the angle [deg] between the cytoplasm
               element's side and the nucleus element's side through each
               node (0: a straight grid line across the interface)

Then per mesh, over the whole nucleus surface (its interior nodes with
one edge into each region): the largest and the median kink [deg] of the
grid line crossing it, and the range of the ratio of those two edges'
lengths (cytoplasm over nucleus: 1 where the spacing is continuous).
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from cellProbes import (interfacePointAt, nucleusEllipse,  # noqa: E402
                        option, regionElements)

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import foamDict, msh   # noqa: E402


def main():
    args = sys.argv[1:]
    props = option(args, "-solidProperties",
                   os.path.join(here, "..", "..", "tutorials", "blast",
                                "axisymmetricPreview", "constant",
                                "solidProperties"))
    if not args:
        sys.exit(__doc__)
    ip = foamDict.read(props)["interfaceProbe"]
    outer, inner = ip["regions"]
    an, cn, zn = nucleusEllipse(props)
    print("%-9s %9s %7s %7s %6s %8s %8s %6s %9s %9s %14s"
          % ("H [um]", "r [um]", "sag", "edge", "t", "thick c", "thick n",
             "patch", "mean", "max", "angle [deg]"))
    for a in args:
        h, path = a.split("=", 1)
        X, groups = msh.read(path)
        eo = regionElements(groups, outer)
        ei = regionElements(groups, inner)
        zs = [X[n][1] for n in {n for e in ei for n in e}]
        z = min(zs) + float(ip["heightFraction"])*(max(zs) - min(zs))
        r, _ = interfacePointAt(path, outer, inner, z)
        # the edge and its elements
        inO = {n for e in eo for n in e}
        inI = {n for e in ei for n in e}
        edge = None
        for e in ei:
            for k in range(4):
                p, q = e[k], e[(k + 1) % 4]
                if p in inO and q in inO and p in inI and q in inI:
                    zp, zq = X[p][1], X[q][1]
                    if (zp - z)*(zq - z) <= 0 and zp != zq:
                        t = (z - zp)/(zq - zp)
                        rr = X[p][0] + t*(X[q][0] - X[p][0])
                        if abs(rr - r) < 1e-15:
                            edge = (p, q, t)
        p, q, t = edge
        P, Qn = X[p], X[q]
        L = math.hypot(Qn[0] - P[0], Qn[1] - P[1])
        # unit normal of the edge's line
        nx, nz = (Qn[1] - P[1])/L, -(Qn[0] - P[0])/L

        def dist(x):
            return (x[0] - P[0])*nx + (x[1] - P[1])*nz

        def owner(elems):
            for e in elems:
                if p in e and q in e:
                    return e
            sys.exit("interfaceGeometry.py: no element on the edge")

        def thick(e):
            far = [n for n in e if n not in (p, q)]
            return abs(sum(dist(X[n]) for n in far)/len(far))

        ec, en = owner(eo), owner(ei)
        patch = [e for e in eo if set(e) & set(ec)]
        cd = [abs(sum(dist(X[n]) for n in e)/4) for e in patch]

        # the exact ellipse's normal at the point, and the sag along it
        zr = (z - zn)/cn
        r0 = an*math.sqrt(max(0.0, 1 - zr*zr))
        # distance from (r, z) to the ellipse, to first order: the level
        # set over its gradient
        F = (r/an)**2 + ((z - zn)/cn)**2 - 1
        G = 2*math.hypot(r/an**2, (z - zn)/cn**2)
        sag = -F/G

        def side(node, e):
            """the side of element e through node off the edge"""
            k = e.index(node)
            for m in (e[(k + 1) % 4], e[(k + 3) % 4]):
                if m not in (p, q):
                    return (X[m][0] - X[node][0], X[m][1] - X[node][1])

        angles = []
        for node in (p, q):
            a1, a2 = side(node, ec), side(node, en)
            # the grid line through node: a1 continued by -a2
            c = -(a1[0]*a2[0] + a1[1]*a2[1])/(math.hypot(*a1)*math.hypot(*a2))
            angles.append(math.degrees(math.acos(max(-1.0, min(1.0, c)))))
        print("%-9s %9.5f %7.3f %7.1f %6.3f %8.1f %8.1f %6d %9.1f %9.1f %6.1f %6.1f"
              % (h, r*1e6, sag*1e9, L*1e9, t, thick(ec)*1e9,
                 thick(en)*1e9, len(patch), 1e9*sum(cd)/len(cd),
                 1e9*max(cd), angles[0], angles[1]))
        del r0
        kinks.append((h, surfaceKinks(X, groups, outer, inner)))
    print()
    print("| H [um] | nodes | largest kink [deg] (at r, z [um]) | median "
          "kink [deg] | edge ratio cytoplasm/nucleus: min..max |")
    print("|---:|---:|---:|---:|---:|")
    for h, (k, ratio, where) in kinks:
        print("| %g | %d | %.2f (%.2f, %.2f) | %.2f | %.2f..%.2f |"
              % (float(h)*1e6, len(k), max(k), where[0]*1e6, where[1]*1e6,
                 sorted(k)[len(k)//2], min(ratio), max(ratio)))


def surfaceKinks(X, groups, outer, inner):
    """kinks [deg], edge ratios and the place [m] of the largest kink over
    the interior nodes of the outer-inner interface"""
    q = {r: regionElements(groups, r) for r in (outer, inner)}
    N = {r: {n for e in q[r] for n in e} for r in q}
    bnd = {n for g in ("fixedBottom", "axis", "outerSurface") if g in groups
           for (_, _, _, nodes) in groups[g][1] for n in nodes}
    iface = (N[outer] & N[inner]) - bnd
    off = {}
    for r in q:
        for e in q[r]:
            for k in range(4):
                for x, y in ((e[k], e[(k + 1) % 4]), (e[(k + 1) % 4], e[k])):
                    if x in iface and y not in iface:
                        off.setdefault((x, r), set()).add(y)
    kinks, ratios, worst = [], [], (0.0, None)
    for n in iface:
        c, m = off.get((n, outer), ()), off.get((n, inner), ())
        if len(c) != 1 or len(m) != 1:
            continue
        c, m = next(iter(c)), next(iter(m))
        u = (X[c][0] - X[n][0], X[c][1] - X[n][1])
        v = (X[n][0] - X[m][0], X[n][1] - X[m][1])
        cs = (u[0]*v[0] + u[1]*v[1])/(math.hypot(*u)*math.hypot(*v))
        k = math.degrees(math.acos(max(-1.0, min(1.0, cs))))
        kinks.append(k)
        ratios.append(math.hypot(*u)/math.hypot(*v))
        if k > worst[0]:
            worst = (k, (X[n][0], X[n][1]))
    return kinks, ratios, worst[1]


kinks = []


if __name__ == "__main__":
    main()
