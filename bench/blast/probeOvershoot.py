#!/usr/bin/python3
"""Where the 3D quarter's solid probe pressure departs from the 1D plane
wave (issue 17; docs/results/blast3D.md, "The probe's pressure overshoot
in 3D"); not a test. Made for the runs of bench/blast/probeOvershoot3D.sh
(hexahedral cell mesh, solid/solid.h5 written every 0.2 ns through the
incident passage).

    bench/blast/probeOvershoot.py CASE [--reference REF.npz] [--dz 50e-9]
                                  [--pulse 5e-9] [--refEnd T]

REF.npz: the 1D answer (neuronFsi.planeWave.column, the case's own law,
schemes and pulse on the full 100 um column, cells of --dz) at heights
0..8.5 um every 50 nm, to the last probe time + 5 ns (or to --refEnd T
[s]: for a case run for its first step only, the exact field's readings
need no run); computed and written there if missing. Prints, for each probe of postProcessing/
solidProbes (the Fig. 10 point, cytoplasm and nucleus side):

 - its patch and recovery weights, rebuilt as solid::PointProbe does (the
   containing element and the elements of its region sharing a node with
   it; a linear least-squares fit of the element averages at their
   centroids, evaluated at the point); the count is checked against the
   probe file's header;
 - the measures (neuronFsi.planeWave.measures: arrival, 1-ns peak over
   the whole history, 1-ns peak of the incident passage, plateau) against
   the 1D answer at the probe's point of: the recovery applied to the
   exact field (each element holding the 1D answer averaged over its
   volume: what the probe reads if the solver were exact), the 1D answer
   averaged over the containing element, the scene's probe, and the same
   recovery applied to the scene's element pressures of solid.h5 (a check
   of the rebuilt weights); where the exact field's recovery reaches its
   incident 1-ns peak and its largest value in the incident window;
 - the containing element's pressure against the 1D answer at its
   centroid's height, and each patch element's own pressure (solid.h5)
   against the 1D answer averaged over that element;
For a probe across the interface (solidProperties' interfaceProbe with
`reading interface`, or a probe's `across`: its pressure read linearly
between the two elements containing the point, one per side; the header
names the other element and the two weights), also the same measures of
that interface reading applied to the exact field and to solid.h5's
elements (the scene's probe is then that reading), its weights checked
against the projection of the point on the segment of the two elements'
centroids rebuilt here.
then, over every element of the cell, the incident 1-ns peak's error of
the element's pressure against the 1D answer averaged over it, by region
and by bins of r = sqrt(x^2 + y^2) and z (means; elements whose incident
window is cut by the echo, near the substrate, are left out of the means).
"""

import argparse
import glob
import os
import re
import sys

import h5py
import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import planeWave as pw
from neuronFsi import postProcessing

PULSE = [50e6, 5e-9]        # amplitude [Pa], duration [s] (the measures; --pulse)
HEIGHTS = np.round(np.arange(0, 8.5e-6 + 1e-12, 0.05e-6), 12)
SIGNS = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                  [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]])


def shape(xi):
    """Trilinear hexahedron (gmsh order): N [8], dN/dxi [8 x 3]."""
    t = 1 + SIGNS*xi
    N = 0.125*t.prod(axis=1)
    dN = 0.125*np.stack([SIGNS[:, 0]*t[:, 1]*t[:, 2],
                         SIGNS[:, 1]*t[:, 0]*t[:, 2],
                         SIGNS[:, 2]*t[:, 0]*t[:, 1]], axis=1)
    return N, dN


def passagePressures(h5, after=5.2e-8):
    """Times [s] and element pressures [Pa] of the writes of solid.h5 after
    `after` [s] (the passage of the pulse), each time read once."""
    steps = h5["steps"]
    sel = [(k, steps[k].attrs["time"]) for k in sorted(steps, key=int)]
    sel = [(k, t) for k, t in sel if t > after]
    return (np.array([t for _, t in sel]),
            np.array([steps[k]["pressure"][()] for k, _ in sel]))


class Cell:
    def __init__(self, h5):
        self.X = h5["mesh/coordinates"][()]
        self.C = h5["mesh/connectivity"][()]
        self.R = h5["mesh/region"][()]
        if self.C.shape[1] != 8:
            sys.exit("probeOvershoot.py: hexahedral cell meshes only")
        self._c = {}

    def quadrature(self, e, n=2):
        x, w = np.polynomial.legendre.leggauss(n)
        Xe = self.X[self.C[e]]
        P, W = [], []
        for i in range(n):
            for j in range(n):
                for k in range(n):
                    N, dN = shape(np.array([x[i], x[j], x[k]]))
                    P.append(N @ Xe)
                    W.append(w[i]*w[j]*w[k]*np.linalg.det(Xe.T @ dN))
        return np.array(P), np.array(W)

    def centroid(self, e):
        if e not in self._c:
            P, W = self.quadrature(e)
            self._c[e] = (W[:, None]*P).sum(0)/W.sum()
        return self._c[e]

    def recovery(self, Xp, host):
        """solid::PointProbe's patch and weights."""
        nodes = set(self.C[host])
        patch = [e for e in range(len(self.C))
                 if self.R[e] == self.R[host] and nodes & set(self.C[e])]
        return patch, self.fitWeights(Xp, patch)

    def fitWeights(self, Xp, patch):
        """Weights of the linear least-squares fit over the centroids of
        patch, evaluated at Xp (solid::PointProbe's construction)."""
        D = np.array([self.centroid(e) - Xp for e in patch])
        D /= np.linalg.norm(D, axis=1).max()
        _, s, Vt = np.linalg.svd(D - D.mean(0))
        k = int((s > 1e-8*s[0]).sum())
        A = np.hstack([np.ones((len(patch), 1)), D @ Vt[:k].T])
        e0 = np.zeros(1 + k)
        e0[0] = 1
        return A @ np.linalg.solve(A.T @ A, e0)


class Reference:
    def __init__(self, path):
        r = np.load(path)
        self.z, self.t, self.p = r["z"], r["t"], r["p"]

    def at(self, z):
        k = int(np.clip(np.searchsorted(self.z, z) - 1, 0, len(self.z) - 2))
        a = (z - self.z[k])/(self.z[k + 1] - self.z[k])
        return (1 - a)*self.p[:, k] + a*self.p[:, k + 1]

    def elementAverage(self, cell, e, n=4):
        P, W = cell.quadrature(e, n)
        return sum(w*self.at(z) for z, w in zip(P[:, 2], W))/W.sum()


def probeHistory(case):
    """The solid probes' file(s), a restart's continuing the first."""
    files = sorted(glob.glob(os.path.join(
        case, "postProcessing", "solidProbes", "*", "solidProbes.dat")),
        key=lambda f: float(os.path.basename(os.path.dirname(f))))
    if not files:
        sys.exit("probeOvershoot.py: %s: no postProcessing/solidProbes" % case)
    header = open(files[0]).read(20000)
    probes = re.findall(r"# probe (\d+) (\S+) at \((\S+) (\S+) (\S+)\) m in "
                        r"(\S+): element (\d+), patch of (\d+)", header)
    data = np.loadtxt(files[0], ndmin=2)
    for f in files[1:]:
        d = np.loadtxt(f, ndmin=2)
        data = np.vstack([data[data[:, 0] < d[0, 0]], d])
    return probes, data


def measure(t, p, tRef, pRef, z):
    s, r = pw.measures(t, p, tRef, pRef, PULSE[0], PULSE[1], max(z, 1e-7))
    e = pw.errors(s, r)
    return {k: (np.nan if v is None else v) for k, v in e.items()}


def whereIncident(t, p, pRef, z):
    """Where the incident 1-ns peak of p(t) (the exact field's recovery)
    is reached: the window centre, the reference's arrival, and p's
    largest value in the incident window (the windows of
    neuronFsi.planeWave.measures at height z)."""
    ta = pw.arrival(t, pRef, PULSE[0])
    end = ta + min(PULSE[1], 2*max(z, 1e-7)/(1.1*1450.0)) - 0.5e-9
    tc, mean = pw.runningMean(t, p, 1e-9)
    inc = (tc >= ta) & (tc <= end)
    k = int(np.argmax(mean[inc]))
    raw = (t >= ta) & (t <= end)
    j = int(np.argmax(p[raw]))
    return ("the exact field's recovery: incident 1-ns peak %.2f MPa at "
            "%.2f ns (the 1D arrival %.2f ns), largest value in the "
            "incident window %.2f MPa at %.2f ns"
            % (mean[inc][k]/1e6, tc[inc][k]*1e9, ta*1e9, p[raw][j]/1e6,
               t[raw][j]*1e9))


def fmt(e):
    return ("arrival %+.2f ns, 1-ns peak %+6.1f %%, incident %+6.1f %%, "
            "plateau %+5.1f %%" % (1e9*e["arrival"], 100*e["peak1ns"],
                                   100*e["peakIncident"], 100*e["plateau"]))


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("case")
    a.add_argument("--reference", default=None)
    a.add_argument("--dz", type=float, default=50e-9)
    a.add_argument("--refEnd", type=float, default=None,
                   help="the end time [s] of the 1D answer when it is "
                   "computed (default: the last probe time + 5 ns)")
    a.add_argument("--pulse", type=float, default=PULSE[1],
                   help="the pulse's duration [s] for the measures' "
                   "windows (default 5e-9; the 1D answer is the case's "
                   "own pulse)")
    o = a.parse_args()
    PULSE[1] = o.pulse
    case = os.path.abspath(o.case)
    probes, data = probeHistory(case)
    refPath = o.reference or os.path.join(case, "ref1d.npz")
    if not os.path.isfile(refPath):
        end = o.refEnd if o.refEnd else data[-1, 0] + 5e-9
        w = pw.column(case, list(HEIGHTS), 1e-4, end, dz=o.dz)
        np.savez(refPath, z=HEIGHTS, t=w.t, p=w.p)
        print("1D answer: %d heights to %.4g s, %g m cells -> %s"
              % (len(HEIGHTS), end, o.dz, refPath))
    ref = Reference(refPath)
    with h5py.File(os.path.join(case, "solid", "solid.h5"), "r") as h5:
        cell = Cell(h5)
        ts, P = passagePressures(h5)
    fine = len(ts) >= 20
    if fine:
        print("solid.h5: %d steps from %.4g to %.4g s (every %.3g s)"
              % (len(ts), ts[0], ts[-1], np.diff(ts).mean()))
    else:
        print("solid.h5 holds %d steps after 52 ns: the element histories "
              "are left out (probeOvershoot3D.sh writes every 0.2 ns)"
              % len(ts))
    for num, name, x, y, z, region, host, nPatch in probes:
        num, host = int(num), int(host)
        Xp = np.array([float(x), float(y), float(z)])
        patch, w = cell.recovery(Xp, host)
        if len(patch) != int(nPatch):
            sys.exit("probeOvershoot.py: probe %d: patch of %d elements, "
                     "the probe file says %s" % (num, len(patch), nPatch))
        pX = ref.at(Xp[2])
        print("\nprobe %d %s (%s) at z = %.3f um: element %d, patch of %d"
              % (num, name, region, Xp[2]*1e6, host, len(patch)))
        across = postProcessing.probes(case)[num]["across"]
        hosts = []
        if across is not None:
            # the two hosts' weights of the header against the projection
            # of the point on the segment of their centroids
            eb = across["element"]
            ca, cb = cell.centroid(host), cell.centroid(eb)
            sb = float(np.clip((Xp - ca) @ (cb - ca)/((cb - ca) @ (cb - ca)),
                               0, 1))
            hosts = [(host, across["weights"][0]), (eb, across["weights"][1])]
            print("   across the interface with %s: element %d (centroid "
                  "%.2f um from the point; the point %.2f um off the "
                  "hosts' segment), weights %.4f / %.4f (the projection "
                  "here: %.4f / %.4f)"
                  % (across["region"], eb, np.linalg.norm(cb - Xp)*1e6,
                     np.linalg.norm(ca + sb*(cb - ca) - Xp)*1e6,
                     hosts[0][1], hosts[1][1], 1 - sb, sb))
            if abs(sb - hosts[1][1]) > 1e-4:
                sys.exit("probeOvershoot.py: probe %d: the header's weights "
                         "are not the projection's" % num)
        for e, we in sorted(zip(patch, w), key=lambda i: i[0] != host):
            c = cell.centroid(e)
            print("   element %5d  centroid r %.2f z %.2f um  weight %+.3f"
                  % (e, np.hypot(c[0], c[1])*1e6, c[2]*1e6, we))
        exact = sum(we*ref.elementAverage(cell, e) for e, we in zip(patch, w))
        rows = [
            ("recovery of the exact field", ref.t, exact),
            ("1D averaged over the element", ref.t,
             ref.elementAverage(cell, host)),
            ("scene's probe" + (" (across)" if hosts else ""), data[:, 0],
             data[:, 1 + 5*num]),
        ] + ([("recovery of solid.h5's elements", ts, P[:, patch] @ w)]
             if fine else [])
        if hosts:
            rows.insert(1, ("across: the exact field", ref.t,
                            sum(we*ref.elementAverage(cell, e)
                                for e, we in hosts)))
            if fine:
                rows.append(("across: solid.h5's elements", ts,
                             sum(we*P[:, e] for e, we in hosts)))
        for label, t, p in rows:
            print("   %-32s %s" % (label, fmt(measure(t, p, ref.t, pX,
                                                       Xp[2]))))
        print("   %s" % whereIncident(ref.t, exact, pX, Xp[2]))
        if hosts:
            print("   across: %s" % whereIncident(
                ref.t, sum(we*ref.elementAverage(cell, e) for e, we in hosts),
                pX, Xp[2]).replace("recovery", "interface reading"))
        if not fine:
            continue
        print("   the containing element against the 1D answer at its "
              "centroid's height: %s"
              % fmt(measure(ts, P[:, host], ref.t,
                            ref.at(cell.centroid(host)[2]),
                            cell.centroid(host)[2])))
        print("   each patch element against the 1D answer averaged over it:")
        for e in sorted(patch, key=lambda i: i != host):
            c = cell.centroid(e)
            print("     element %5d (z %.2f um): %s"
                  % (e, c[2]*1e6, fmt(measure(ts, P[:, e], ref.t,
                                              ref.elementAverage(cell, e, 2),
                                              c[2]))))
    if not fine:
        return
    # the whole cell
    err = np.full(len(cell.C), np.nan)
    rz = np.array([(np.hypot(c[0], c[1]), c[2]) for c in
                   (cell.centroid(e) for e in range(len(cell.C)))])
    for e in range(len(cell.C)):
        err[e] = measure(ts, P[:, e], ref.t, ref.elementAverage(cell, e, 2),
                         rz[e, 1])["peakIncident"]
    rb = [0, 1, 2.5, 4, 6, 9.5]
    zb = [0, 1.5, 3, 4.5, 6, 8]
    print("\nincident 1-ns peak of each element's pressure against the 1D "
          "answer averaged over it: mean [%%] (elements); rows r [um], "
          "columns z [um] %s" % " ".join("%g-%g" % (zb[i], zb[i + 1])
                                           for i in range(len(zb) - 1)))
    for reg in np.unique(cell.R):
        m = cell.R == reg
        print(" region %d (%d elements): mean %+.1f %%, median %+.1f %%"
              % (reg, m.sum(), 100*np.nanmean(err[m]),
                 100*np.nanmedian(err[m])))
        for i in range(len(rb) - 1):
            line = []
            for j in range(len(zb) - 1):
                mm = (m & (rz[:, 0]*1e6 >= rb[i]) & (rz[:, 0]*1e6 < rb[i + 1])
                      & (rz[:, 1]*1e6 >= zb[j]) & (rz[:, 1]*1e6 < zb[j + 1])
                      & np.isfinite(err))
                line.append("%+6.1f (%3d)" % (100*err[mm].mean(), mm.sum())
                            if mm.any() else "     -      ")
            print("   r %3g-%3g: %s" % (rb[i], rb[i + 1], " ".join(line)))


if __name__ == "__main__":
    main()
