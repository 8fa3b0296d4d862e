#!/usr/bin/python3
"""The solid's element in 1D: how much a chain of Q1/P0 elements with the
lumped mass, central differences and the Abaqus-form bulk viscosity
(solid::MieGruneisenVolumetric: q = b1 rho c h |d| + b2^2 rho h^2 d^2 in
compression) overshoots the plane wave it carries (docs/results/
blast3D.md, "The probe's pressure overshoot in 3D"); not a test.

    bench/blast/elementChain1D.py REF.npz H [--b1 0.06] [--b2 1.2]
                                  [--dt 4.2e-11] [--top 7.9e-6]
                                  [--pulse 5e-9] [--smear 0]
                                  [--case CASE [--endTime 8e-8]]

REF.npz: the 1D answer on a grid of heights (bench/blast/probeOvershoot.py
writes it: the case's own law and pulse, 50 nm cells). The chain: linear
acoustics (K = rho c^2, water: 1000 kg/m^3, 1450 m/s), elements of about
H [m] from the substrate (fixed) to --top (the cell's height on the axis),
the top node loaded by the 1D answer's pressure there, time step --dt
(the coupled 3D quarter's, set by the water). Prints, for the elements 1,
2, 3 and 4 um below the top, the measures (neuronFsi.planeWave) of the
element's pressure (with q, as the solid reports it) against the 1D answer
averaged over the element; only the incident passage is meaningful (the
loaded top reflects what the chain's own echo differs by).

--pulse: the pulse's duration [s] for the measures' windows (the 1D
answer in REF.npz is the case's own pulse). --smear S [m]: the load on
the top node is the 1D answer's running mean over S/C in time (a front
spread over S of water, as a water mesh of size about S hands it to the
cell; 0: the 1D answer itself). --case CASE: if REF.npz does not exist,
it is computed first from CASE as bench/blast/probeOvershoot.py does
(heights 0..8.5 um every 50 nm, 50 nm cells, to --endTime) and written
there.
"""

import argparse
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import planeWave as pw

RHO, C = 1000.0, 1450.0
HEIGHTS = np.round(np.arange(0, 8.5e-6 + 1e-12, 0.05e-6), 12)  # as probeOvershoot.py


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("reference")
    a.add_argument("h", type=float)
    a.add_argument("--b1", type=float, default=0.06)
    a.add_argument("--b2", type=float, default=1.2)
    a.add_argument("--dt", type=float, default=4.2e-11)
    a.add_argument("--top", type=float, default=7.9e-6)
    a.add_argument("--pulse", type=float, default=5e-9)
    a.add_argument("--smear", type=float, default=0.0)
    a.add_argument("--case", default=None)
    a.add_argument("--endTime", type=float, default=8e-8)
    o = a.parse_args()
    if not os.path.isfile(o.reference):
        if o.case is None:
            sys.exit("elementChain1D.py: %s not found (give --case CASE to "
                     "compute it)" % o.reference)
        w = pw.column(os.path.abspath(o.case), list(HEIGHTS), 1e-4,
                      o.endTime, dz=50e-9)
        np.savez(o.reference, z=HEIGHTS, t=w.t, p=w.p)
        print("1D answer: %d heights to %.4g s, 50 nm cells -> %s"
              % (len(HEIGHTS), o.endTime, o.reference))
    r = np.load(o.reference)
    zg, tg, pg = r["z"], r["t"], r["p"]

    def p1D(z):
        k = int(np.clip(np.searchsorted(zg, z) - 1, 0, len(zg) - 2))
        w = (z - zg[k])/(zg[k + 1] - zg[k])
        return (1 - w)*pg[:, k] + w*pg[:, k + 1]

    n = max(1, int(round(o.top/o.h)))
    h = o.top/n
    K = RHO*C*C
    top = p1D(o.top)
    if o.smear > 0:
        # the running mean over S/C: a front spread over S of water
        tc, mean = pw.runningMean(tg, top, o.smear/C)
        top = np.interp(tg, tc, mean)
    m = np.full(n + 1, RHO*h)
    m[0] = m[-1] = 0.5*RHO*h
    u = np.zeros(n + 1)
    v = np.zeros(n + 1)

    def force(u, v, t):
        d = np.diff(v)/h                    # strain rate (< 0: compression)
        q = np.where(d < 0, -o.b1*RHO*C*h*d + o.b2**2*RHO*h*h*d*d, 0.0)
        p = -K*np.diff(u)/h + q             # element pressure, + compression
        f = np.zeros(n + 1)
        f[1:] += p                          # pushes the node above up
        f[:-1] -= p                         # and the node below down
        f[-1] -= np.interp(t, tg, top)      # the load on the top face
        return f, p

    t, tEnd = tg[0], tg[-1]
    a0 = force(u, v, t)[0]/m
    a0[0] = 0
    ts, ps = [], []
    while t < tEnd - o.dt:
        v += 0.5*o.dt*a0
        u += o.dt*v
        t += o.dt
        # the bulk viscosity on the mid-step velocity, as the solver's
        f, p = force(u, v, t)
        a0 = f/m
        a0[0] = 0
        v += 0.5*o.dt*a0
        ts.append(t)
        ps.append(p)
    ts, ps = np.array(ts), np.array(ps)
    zc = (np.arange(n) + 0.5)*h
    print("chain: %d elements of %.3g um, b1 %g, b2 %g, dt %.3g s, "
          "pulse %.3g s, load smeared over %.3g um of water"
          % (n, h*1e6, o.b1, o.b2, o.dt, o.pulse, o.smear*1e6))
    for depth in (1e-6, 2e-6, 3e-6, 4e-6):
        e = int(np.argmin(abs(zc - (o.top - depth))))
        ref = np.mean([p1D(z) for z in zc[e] + h*np.linspace(-0.5, 0.5, 21)],
                      axis=0)
        s, rr = pw.measures(ts, ps[:, e], tg, ref, 50e6, o.pulse, zc[e])
        er = pw.errors(s, rr)
        ta = rr["arrival"]
        print("  element at z %.2f um (%.2f um below the top): arrival "
              "%+.2f ns, incident 1-ns peak %+.1f %%, largest pressure in "
              "the 3 ns after the arrival %.1f MPa (1D: %.1f MPa)"
              % (zc[e]*1e6, (o.top - zc[e])*1e6, er["arrival"]*1e9,
                 100*er["peakIncident"],
                 ps[(ts >= ta) & (ts <= ta + 3e-9), e].max()/1e6,
                 ref[(tg >= ta) & (tg <= ta + 3e-9)].max()/1e6))


if __name__ == "__main__":
    main()
