#!/usr/bin/python3
"""Where the pulse study's nucleus indicators come from (docs/results/
pulseStudy.md, "Against the former default"; not a test).

    bench/blast/nucleusIndicators.py CASE [--window 1e-9] [--exact]
                                     [--from 60e-9] [--to 95e-9]

CASE: a blast preview case (r-z) with solid/solid.h5. For every write in
[--from, --to]: the nucleus's largest principal Green-Lagrange strain E1
(neuronFsi.damageIndicators, the pulse study's definition: F at the
element's centre), the element and its centroid (r, z), the largest E1
away from the axis (r > 0.5 um) and the rms over the nucleus, and the
largest von Mises stress with its element and away from the axis; then the
nucleus's largest rate over --window (the study's strainRate: the
largest principal magnitude of the change of E over the window, which
needs writes --window apart), its element, time and zz component. With
--exact, the 1D plane wave of the case's column (neuronFsi.planeWave.
column, 50 nm cells) gives the same window's largest |change of E_zz| /
window at a few heights, E_zz = (lambda^2 - 1)/2 with lambda =
rho0/rho (uniaxial strain; exact E1 is 0).
"""
import argparse

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import bench, damageIndicators as di, planeWave
from neuronFsi.solidResults import SolidResults

NUCLEUS = 0          # region numbers of solid.h5 (bench/blast/interfaceProfile.py)
RHO0 = 1000.0        # the nucleus's reference density [kg/m^3]
HEIGHTS = (0.0, 0.175e-6, 0.35e-6, 1e-6, 4.108e-6)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--window", type=float, default=1e-9)
    ap.add_argument("--exact", action="store_true")
    ap.add_argument("--from", dest="t0", type=float, default=60e-9)
    ap.add_argument("--to", dest="t1", type=float, default=95e-9)
    a = bench.parse(ap)
    with SolidResults(a.case + "/solid/solid.h5") as s:
        X = s.mesh("coordinates")
        conn = s.mesh("connectivity")
        region = s.mesh("region")
        c = X[conn, :2].mean(axis=1)
        n = np.where(region == NUCLEUS)[0]
        off = n[c[n, 0] > 0.5e-6]
        steps = s.steps()
        t = np.array([s.time(k) for k in steps])
        E, best = {}, None
        print("# t[ns] E1max[-] element r[um] z[um] E1maxOffAxis[-] "
              "E1rms[-] vonMisesMax[Pa] element r[um] z[um] "
              "vonMisesMaxOffAxis[Pa]")
        for j, k in enumerate(steps):
            if t[j] < a.t0 - a.window*(1 + 1e-6) or t[j] > a.t1:
                continue
            E[j] = di.greenLagrange(di.centreGradient(
                X, conn, s.field(k, "displacement")))
            back = [i for i in E if abs(t[i] - (t[j] - a.window))
                    <= 1e-6*a.window]
            if back:
                dE = (E[j] - E[back[-1]])/a.window
                rate = di.largestMagnitude(dE)
                e = n[np.argmax(rate[n])]
                if best is None or rate[e] > best[0]:
                    best = (rate[e], t[j], e, dE[e, 1, 1])
            for old in [i for i in E if t[i] < t[j] - 1.5*a.window]:
                del E[old]
            if t[j] < a.t0:
                continue
            e1 = di.largestPrincipal(E[j])
            e = n[np.argmax(e1[n])]
            vm = s.field(k, "vonMises")
            v = n[np.argmax(vm[n])]
            print("%.2f %.4g %d %.2f %.2f %.4g %.4g %.4g %d %.2f %.2f %.4g" % (
                t[j]*1e9, e1[e], e, c[e, 0]*1e6, c[e, 1]*1e6,
                e1[off].max(), np.sqrt(np.mean(e1[n]**2)), vm[v], v,
                c[v, 0]*1e6, c[v, 1]*1e6, vm[off].max()))
    if best is None:
        print("# no two writes %g s apart: no rate" % a.window)
    else:
        r, tb, e, zz = best
        print("# largest %g s rate in the nucleus %.4g 1/s at %.2f ns, element"
              " %d at (%.2f, %.2f) um, its zz component %.4g 1/s" % (
                  a.window, r, tb*1e9, e, c[e, 0]*1e6, c[e, 1]*1e6, zz))
    if a.exact:
        Z = planeWave.inflowColumnHeight(a.case) or 100e-6
        w = planeWave.column(a.case, list(HEIGHTS), Z, a.t1, dz=50e-9)
        wt = np.asarray(w.t)
        g = np.arange(wt[0] + a.window, wt[-1], a.window/100)
        for z in HEIGHTS:
            lam = RHO0/np.asarray(w.densityAt(z))
            ezz = 0.5*(lam**2 - 1)
            d = np.interp(g, wt, ezz) - np.interp(g - a.window, wt, ezz)
            print("# exact (1D plane wave) at z = %.3f um: largest |change of"
                  " E_zz| over %g s / %g s = %.4g 1/s" % (
                      z*1e6, a.window, a.window, np.abs(d).max()/a.window))


if __name__ == "__main__":
    bench.main(main)
