#!/usr/bin/python3
"""Measures of a pulseLayer run (50 MPa, 5 ns pulse in water crossing into
a solid layer with water's EOS on a rigid wall):
 - reflection: largest |p| in the fluid probe (x = 25 um) after the
   incident pulse has passed it (t > 30 ns) and before the wall echo can
   return (t < 100 ns), in % of the 50 MPa incident amplitude;
 - arrival: first time the solid probe at x = 75 um exceeds 25 MPa [ns];
 - wall: peak pressure of the solid element at the wall [MPa];
 - interface: largest interface pressure (x force of the coupling log over
   the 1 um x 1 um cross-section) [MPa], and its exact value for a
   solid of density rho0s with water's C0 and s: the transmitted shock
   p = rho0s (C0 + s u) u meets the water's reflected wave, a shock
   (rho0s > rho0) or a rarefaction integrated along the Hugoniot as the
   isentrope (rho0s < rho0; third order in the shock strength);
 - coupling: steps, mean/max iterations, non-converged steps.
Usage: analysePulseLayer.py <case> <rho0s>   (one line of key=value)"""
import sys
import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi.postProcessing import series

case = sys.argv[1]
rho0s = float(sys.argv[2])
rho0, C0, s, pInc = 1000.0, 1450.0, 1.99, 50e6


def hugoniotP(r0, u):
    return r0*(C0 + s*u)*u


def bisect(f, a, b):
    for _ in range(200):
        m = 0.5*(a + b)
        if f(a)*f(m) <= 0:
            b = m
        else:
            a = m
    return 0.5*(a + b)


def exactInterface():
    u1 = bisect(lambda u: hugoniotP(rho0, u) - pInc, 0, 100)
    if rho0s == rho0:
        return pInc
    if rho0s > rho0:
        # reflected shock into the moving, compressed water: in the frame
        # of state 1, the water Hugoniot from state 1 (weak, relative to
        # the 50 MPa state with its density rho1)
        rho1 = rho0*(C0 + s*u1)/(C0 + s*u1 - u1)
        c1 = C0 + 2*s*u1  # dp/du slope of the Hugoniot / rho: local speed
        f = lambda u: hugoniotP(rho0s, u) - (
            pInc + rho1*(c1 + s*(u1 - u))*(u1 - u))
        return hugoniotP(rho0s, bisect(f, 0, u1))
    # rarefaction: u = u1 + int_p^p1 dp/(rho c) along the Hugoniot
    us = np.linspace(0, u1, 20001)
    ps = hugoniotP(rho0, us)
    rhos = rho0*(C0 + s*us)/(C0 + s*us - us)
    dpdrho = np.gradient(ps, rhos)
    rc = rhos*np.sqrt(dpdrho)
    # cumulative integral of dp/(rho c) from p to p1
    g = 1/rc
    cum = np.concatenate(([0], np.cumsum(0.5*(g[1:] + g[:-1])*np.diff(ps))))
    uR = u1 + (cum[-1] - cum)
    # the difference decreases with p: reverse for np.interp
    return np.interp(0, (hugoniotP(rho0s, uR) - ps)[::-1], ps[::-1])

fp = series(case, "probes/p")
sp = series(case, "solidProbes/solidProbes.dat")
cp = series(case, "fsi/coupling.dat")

t = fp[:, 0]
after = (t > 30e-9) & (t < 100e-9)
reflection = 100*np.max(np.abs(fp[after, 1]))/50e6 if after.any() else -1

ts = sp[:, 0]
p75 = sp[:, 1]
above = np.nonzero(p75 > 25e6)[0]
if len(above):
    i = above[0]
    # linear interpolation of the 25 MPa crossing
    arrival = 1e9*(ts[i - 1] + (25e6 - p75[i - 1])*(ts[i] - ts[i - 1])
                   /(p75[i] - p75[i - 1]))
else:
    arrival = -1
wall = np.max(sp[:, 6])/1e6
incident = np.max(p75)/1e6

interface = np.max(cp[:, 5])/1e-12/1e6
exact = exactInterface()/1e6
it = cp[:, 2]
print(f"reflection={reflection:.3f}% arrival={arrival:.3f}ns "
      f"wall={wall:.2f}MPa incident75={incident:.2f}MPa "
      f"interface={interface:.3f}MPa interfaceExact={exact:.3f}MPa "
      f"steps={len(it)} meanIter={it.mean():.2f} maxIter={int(it.max())} "
      f"nonConverged={int(np.sum(cp[:, 4] == 0))} "
      f"maxResidual={cp[:, 3].max():.2e} maxGcl={cp[:, 9].max():.1e}")
