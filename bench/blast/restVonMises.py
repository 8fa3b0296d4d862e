#!/usr/bin/python3
"""What makes the 3D quarter's von Mises after the pulse (issue 17 item 6;
docs/results/blast3D.md, "The von Mises at rest in 3D"); not a test. Reads
a run of tutorials/blast/quarter3D (hexahedral cell mesh; solid/solid.h5
with the states written at the case's write times) and prints, at the
step nearest --time (default: the last):

 - the cell's elements: von Mises of the written (volume-averaged) Cauchy
   stress, by region and by bins of r = sqrt(x^2 + y^2) and z, and for
   the elements touching another region against those that do not;
 - a check that the written stress is the material's response to the
   written displacements: the deviatoric Cauchy stress rebuilt from the
   nodal displacements at the 2x2x2 Gauss points, (mu0 + sum mu_k)/J
   dev(b_bar) (the Maxwell branches elastic: tau >= 0.01 s against a
   150 ns run), averaged over the element's current volume, against the
   written one; and the branch's internal variable Q (restart/pointState)
   against beta S_iso(C) (what it holds if it only follows the spring);
 - the deviatoric stress split into cylindrical components (r, theta, z
   about the axis x = y = 0), root mean square over each region;
 - the nodes' velocity (exact: 0), v_r and v_z, mean over bins of r, z;
 - for each probe of postProcessing/solidProbes: its patch and weights
   (solid::PointProbe's, rebuilt as bench/blast/probeOvershoot.py does),
   von Mises of the recovered stress (what the probe writes), the
   weighted mean of the patch's von Mises, the containing element's, and
   the probe file's value at that time; the recovered deviatoric stress'
   components and the part of it each patch element contributes.

    bench/blast/restVonMises.py CASE [--time 1.5e-7] [--history]
                                     [--fluid TIME ...]

--history: instead, per written step of solid.h5, the mean element von
Mises of each region, over each probe's patch the mean von Mises and the
mean cylindrical components rz, rr, zz of the deviatoric stress, the
solid's mean and largest nodal speed and largest displacement, and its
lateral speed sqrt(v_x^2 + v_y^2) (exact: 0): the mean over the nodes of
each kind (of one region, or shared by two) and the largest, with where.
--fluid TIME ...: instead, the water's speed at those OpenFOAM times, by
the cell's ellipsoidal distance d = sqrt((r/9.5 um)^2 + (z/8.5 um)^2)
(the cell: d <= 1); needs the cell centres written first:
`postProcess -case CASE -func writeCellCentres -time 'T1,T2'`.

The exact (uniaxial-strain) answer is at rest after the pulse: F = I, von
Mises 0 (planeWave -check compares the probe's von Mises after 140 ns with
its 1-ns peak; bound 0.1).
"""

import argparse
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from probeOvershoot import Cell, probeHistory, shape  # noqa: E402
from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import planeWave as pw  # noqa: E402

NQ = 8          # Gauss points per hexahedron (2x2x2)
NHIST = 13      # Viscoelastic point history: S_iso,n (6) | Q (6) | D (1)
VOIGT = [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (0, 2)]


def vonMises(s):
    d = s - np.trace(s)/3*np.eye(3)
    return np.sqrt(1.5*(d*d).sum())


def dev(s):
    return s - np.trace(s)/3*np.eye(3)


def gaussPoints():
    """The 2x2x2 points in the order of solid::ElementGeometry (gmsh's
    tensor order: i over xi fastest)."""
    g = 1/np.sqrt(3)
    return [np.array([a, b, c]) for c in (-g, g) for b in (-g, g)
            for a in (-g, g)]


def cylindrical(c):
    """Rows: e_r, e_theta, e_z at centroid c."""
    r = np.hypot(c[0], c[1])
    if r < 1e-12:
        er = np.array([1.0, 0, 0])
    else:
        er = np.array([c[0]/r, c[1]/r, 0])
    return np.array([er, [-er[1], er[0], 0], [0, 0, 1.0]])


def history(case):
    probes, _ = probeHistory(case)
    with h5py.File(os.path.join(case, "solid", "solid.h5"), "r") as h5:
        cell = Cell(h5)
        keys = sorted(h5["steps"], key=int)
        steps = [(h5["steps"][k].attrs["time"],
                  h5["steps"][k]["cauchyStress"][()].reshape(-1, 3, 3),
                  h5["steps"][k]["velocity"][()],
                  h5["steps"][k]["displacement"][()]) for k in keys]
    ne = len(cell.C)
    R = [cylindrical(cell.centroid(e)) for e in range(ne)]
    patches = []
    for num, name, x, y, z, region, host, nPatch in probes:
        if any(p[1] == region for p in patches):
            continue
        Xp = np.array([float(x), float(y), float(z)])
        patches.append((int(num), region, cell.recovery(Xp, int(host))[0]))
    regions = np.unique(cell.R)
    names = {int(cell.R[int(p[6])]): p[5] for p in probes}
    nodeRegions = {}
    for e in range(ne):
        for n in cell.C[e]:
            nodeRegions.setdefault(int(n), set()).add(int(cell.R[e]))
    kindOf = np.array(["/".join(names.get(r, str(r)) for r in
                                sorted(nodeRegions[n]))
                       for n in range(len(cell.X))])
    kinds = sorted(set(kindOf), key=lambda k: (k.count("/"), k))
    print("t [ns] | mean von Mises per region %s [Pa] | per probe patch "
          "(%s): von Mises, dev rz, rr, zz [Pa] | solid speed mean, max "
          "[m/s] | max |u| [nm] | lateral speed mean over the nodes of "
          "%s [m/s], largest [m/s] at (r, z) [um]"
          % (" ".join(names.get(int(r), str(r)) for r in regions),
             ", ".join(p[1] for p in patches), ", ".join(kinds)))
    for t, sig, v, u in steps:
        vm = np.array([vonMises(x) for x in sig])
        line = "%7.2f | %s |" % (t*1e9, " ".join("%5.2f" % vm[cell.R == r]
                                                 .mean() for r in regions))
        for _, _, patch in patches:
            d = np.array([R[e] @ dev(sig[e]) @ R[e].T for e in patch]
                         ).mean(0)
            line += " %5.2f %+5.2f %+5.2f %+5.2f |" % (
                vm[patch].mean(), d[0, 2], d[0, 0], d[2, 2])
        sp = np.linalg.norm(v, axis=1)
        line += " %.3f %.3f | %5.1f |" % (sp.mean(), sp.max(),
                                           np.abs(u).max()*1e9)
        lat = np.hypot(v[:, 0], v[:, 1])
        i = int(np.argmax(lat))
        line += " %s | %.3f at (%.2f, %.2f)" % (
            " ".join("%.3f" % lat[kindOf == k].mean() for k in kinds),
            lat[i], np.hypot(*cell.X[i, :2])*1e6, cell.X[i, 2]*1e6)
        print(line)


def fluid(case, times):
    from neuronFsi import foamField as ff
    for t in times:
        d = os.path.join(case, t)
        C = ff.internalField(os.path.join(d, "C"))
        U = ff.internalField(os.path.join(d, "U"))
        dist = np.sqrt((C[:, 0]**2 + C[:, 1]**2)/9.5e-6**2
                       + C[:, 2]**2/8.5e-6**2)
        s = np.linalg.norm(U, axis=1)
        print("water at %s s (%d cells): speed mean / max [m/s] by the "
              "ellipsoidal distance d:" % (t, len(C)))
        for lo, hi in ((0, 1.2), (1.2, 1.5), (1.5, 2), (2, 3), (3, 1e9)):
            m = (dist >= lo) & (dist < hi)
            print("   d %3g-%-5g (%5d cells): %.4f / %.4f"
                  % (lo, hi if hi < 1e9 else np.inf, m.sum(), s[m].mean(),
                     s[m].max()))


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("case")
    a.add_argument("--time", type=float, default=None)
    a.add_argument("--history", action="store_true")
    a.add_argument("--fluid", nargs="+", default=None)
    o = a.parse_args()
    case = os.path.abspath(o.case)
    if o.history:
        return history(case)
    if o.fluid:
        return fluid(case, o.fluid)
    with h5py.File(os.path.join(case, "solid", "solid.h5"), "r") as h5:
        cell = Cell(h5)
        keys = sorted(h5["steps"], key=int)
        times = np.array([h5["steps"][k].attrs["time"] for k in keys])
        k = (len(keys) - 1 if o.time is None
             else int(np.argmin(abs(times - o.time))))
        s = h5["steps"][keys[k]]
        t = times[k]
        sig = s["cauchyStress"][()].reshape(-1, 3, 3)
        U = s["displacement"][()]
        pointState = s["restart/pointState"][()]
        vmW = s["vonMises"][()]
        vel = s["velocity"][()]
    ne = len(cell.C)
    print("%s: step at %.4g s (%d elements)" % (case, t, ne))
    # the region names and laws from the probe file and solidProperties
    probes, data = probeHistory(case)
    regionOf = {}
    for num, name, x, y, z, region, host, nPatch in probes:
        regionOf[int(cell.R[int(host)])] = region
    mats = {}
    for rid, rname in regionOf.items():
        rho0, mu0, br = pw.solidMaterial(case, rname)
        mats[rid] = (rname, mu0, [m for m, _ in br])
    vm = np.array([vonMises(sig[e]) for e in range(ne)])
    print("von Mises of the written stress, max |difference| to the "
          "written vonMises: %.3g Pa" % np.abs(vm - vmW).max())

    # rebuilt from the displacements (regions with a known law)
    gp = gaussPoints()
    maxDiff, maxQ, maxVm = 0.0, 0.0, 0.0
    for e in range(ne):
        rid = int(cell.R[e])
        if rid not in mats:
            continue
        _, mu0, mus = mats[rid]
        Xe = cell.X[cell.C[e]]
        ue = U[cell.C[e]]
        acc, vol = np.zeros((3, 3)), 0.0
        for q, xi in enumerate(gp):
            N, dN = shape(xi)
            J0 = Xe.T @ dN
            dNdX = dN @ np.linalg.inv(J0)
            F = np.eye(3) + ue.T @ dNdX
            J = np.linalg.det(F)
            bb = J**(-2/3)*F @ F.T
            w = np.linalg.det(J0)*J
            acc += w*(mu0 + sum(mus))/J*dev(bb)
            vol += w
            # the branch's Q against beta S_iso,n (both stored)
            h = pointState[(e*NQ + q)*NHIST:(e*NQ + q + 1)*NHIST]
            Siso, Q = h[0:6], h[6:12]
            beta = sum(mus)/mu0
            maxQ = max(maxQ, np.abs(Q - beta*Siso).max())
        sd = acc/vol
        maxDiff = max(maxDiff, np.abs(sd - dev(sig[e])).max())
        maxVm = max(maxVm, vm[e])
    print("deviatoric Cauchy stress rebuilt from the displacements "
          "((mu0 + mu1)/J dev(b_bar), 2x2x2 points) against the written: "
          "max |difference| %.3g Pa (largest element von Mises %.3g Pa)"
          % (maxDiff, maxVm))
    print("Maxwell branch: max |Q - beta S_iso| over the points %.3g Pa"
          % maxQ)

    # the cell: by region, by interface contact, by bins
    nodeRegions = {}
    for e in range(ne):
        for n in cell.C[e]:
            nodeRegions.setdefault(n, set()).add(int(cell.R[e]))
    touches = np.array([any(len(nodeRegions[n]) > 1 for n in cell.C[e])
                        for e in range(ne)])
    cen = np.array([cell.centroid(e) for e in range(ne)])
    r = np.hypot(cen[:, 0], cen[:, 1])*1e6
    z = cen[:, 2]*1e6
    rb = [0, 1, 2.5, 4, 6, 9.5]
    zb = [0, 1.5, 3, 4.5, 6, 8]
    for rid in np.unique(cell.R):
        m = cell.R == rid
        name = mats.get(int(rid), ("region %d" % rid,))[0]
        print("\n%s (%d elements): von Mises mean %.3g, median %.3g, max "
              "%.3g Pa; touching another region (%d): mean %.3g Pa, the "
              "others (%d): mean %.3g Pa"
              % (name, m.sum(), vm[m].mean(), np.median(vm[m]), vm[m].max(),
                 (m & touches).sum(),
                 vm[m & touches].mean() if (m & touches).any() else np.nan,
                 (m & ~touches).sum(),
                 vm[m & ~touches].mean() if (m & ~touches).any() else np.nan))
        print("   mean von Mises [Pa] (elements); rows r [um], columns z "
              "[um] %s" % " ".join("%g-%g" % (zb[i], zb[i + 1])
                                   for i in range(len(zb) - 1)))
        for i in range(len(rb) - 1):
            line = []
            for j in range(len(zb) - 1):
                mm = (m & (r >= rb[i]) & (r < rb[i + 1]) & (z >= zb[j])
                      & (z < zb[j + 1]))
                line.append("%6.2f (%3d)" % (vm[mm].mean(), mm.sum())
                            if mm.any() else "     -      ")
            print("   r %3g-%3g: %s" % (rb[i], rb[i + 1], " ".join(line)))
        # cylindrical components, rms over the region
        comp = np.array([[(R @ dev(sig[e]) @ R.T)[i, j] for i, j in VOIGT]
                         for e in np.where(m)[0]
                         for R in [cylindrical(cen[e])]])
        print("   deviatoric stress, rms over the region [Pa]: rr %.3g, "
              "tt %.3g, zz %.3g, rt %.3g, tz %.3g, rz %.3g"
              % tuple(np.sqrt((comp**2).mean(0))[[0, 1, 2, 3, 4, 5]]))

    # the nodes' velocity (exact: 0), binned
    rn = np.hypot(cell.X[:, 0], cell.X[:, 1])
    er = (np.stack([cell.X[:, 0], cell.X[:, 1]], 1)
          / np.maximum(rn, 1e-12)[:, None])
    vr = (vel[:, :2]*er).sum(1)
    print("\nnodal velocity v_r / v_z [m/s] (nodes), mean over bins; rows r "
          "[um], columns z [um] %s" % " ".join("%g-%g" % (zb[i], zb[i + 1])
                                                for i in range(len(zb) - 1)))
    for i in range(len(rb) - 1):
        line = []
        for j in range(len(zb) - 1):
            zn = cell.X[:, 2]*1e6
            mm = ((rn*1e6 >= rb[i]) & (rn*1e6 < rb[i + 1])
                  & (zn >= zb[j]) & (zn < zb[j + 1]))
            line.append("%+.3f/%+.3f (%3d)" % (vr[mm].mean(),
                                               vel[mm, 2].mean(), mm.sum())
                        if mm.any() else "       -           ")
        print("   r %3g-%3g: %s" % (rb[i], rb[i + 1], " ".join(line)))

    # the probes
    tp = data[:, 0]
    kp = int(np.argmin(abs(tp - t)))
    for num, name, x, y, zz, region, host, nPatch in probes:
        num, host = int(num), int(host)
        Xp = np.array([float(x), float(y), float(zz)])
        patch, w = cell.recovery(Xp, host)
        R = cylindrical(Xp)
        rec = sum(we*sig[e] for e, we in zip(patch, w))
        print("\nprobe %d %s (%s), t = %.4g s: von Mises of the recovered "
              "stress %.3g Pa (the probe file at %.4g s: %.3g Pa); weighted "
              "mean of the patch's von Mises %.3g Pa; mean %.3g Pa; the "
              "containing element's %.3g Pa; sum |w| %.2f"
              % (num, name, region, t, vonMises(rec), tp[kp],
                 data[kp, 2 + 5*num],
                 sum(we*vm[e] for e, we in zip(patch, w)),
                 np.mean([vm[e] for e in patch]), vm[host],
                 np.abs(w).sum()))
        d = R @ dev(rec) @ R.T
        print("   recovered deviatoric stress, cylindrical [Pa]: rr %+.3g "
              "tt %+.3g zz %+.3g rt %+.3g tz %+.3g rz %+.3g"
              % tuple(d[i, j] for i, j in VOIGT))
        print("   element  centroid r, z [um]  weight  von Mises [Pa]  "
              "deviatoric rr tt zz rt tz rz [Pa]")
        for e, we in sorted(zip(patch, w), key=lambda i: i[0] != host):
            de = R @ dev(sig[e]) @ R.T
            print("   %6d   %5.2f %5.2f   %+.3f   %6.3f   %s"
                  % (e, r[e], z[e], we, vm[e],
                     " ".join("%+6.2f" % de[i, j] for i, j in VOIGT)))


if __name__ == "__main__":
    main()
