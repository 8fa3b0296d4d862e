#!/usr/bin/python3
"""Assertions on a run of tutorials/blast/axisymmetricPreview (smoke.sh):
map check, arrival time at the probe, coupling convergence.
usage: checkPreview.py case Z"""
import math
import sys
import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import logs, postProcessing
from neuronFsi.checks import Checks

case, Z = script.arguments(2, "checkPreview.py case Z")[:2]
Z = float(Z)
a, H = 8.4e-6, 7.9e-6
check = Checks()


(fr, fz, _), (sr, sz, _) = logs.fsiMapCheck(f"{case}/log.cellBlastFoam")
check.relative("map conservation, radial", sr, fr, 1e-12)
check.relative("map conservation, axial", sz, fz, 1e-12)
check.relative("axial ring force = -pi a^2", fz, -math.pi*a*a, 1e-9)
check.relative("radial ring force ~ -pi^2 a H/2", fr, -math.pi**2*a*H/2,
               1e-3)

# Arrival at the probe (its reference point from the header)
log = "solidProbes/solidProbes.dat"
zc = postProcessing.probes(case, log)[0]["point"][1]
d = postProcessing.series(case, log)
t, p = d[:, 0], d[:, 1]
rho0, C0, s, pulse = 1000.0, 1450.0, 1.99, 50e6
up = (-C0 + math.sqrt(C0**2 + 4*s*pulse/rho0))/(2*s)
Us = C0 + s*up
# Arrival: the front's mid-point, p > half of the probe's own peak (the
# coarse far column of the smoke run lowers the peak of the 5 ns pulse)
if p.max() < 0.5*pulse:
    check(False, "the pulse reached the probe with "
          f"{p.max()/1e6:.3g} MPa only")
    sys.exit(1)
arrival = t[np.argmax(p > p.max()/2)]
check.relative(f"arrival at the probe (z = {zc*1e6:.3f} um, Us = {Us:.2f} "
               "m/s) [s]", arrival, 0.05e-9 + (Z - zc)/Us, 0.03)

c = postProcessing.series(case, "fsi/coupling.dat")
nc = int(np.sum(c[:, 4] == 0))
check(nc == 0, f"coupling: {len(c)} steps, "
      f"iterations mean {c[:, 2].mean():.2f} max {int(c[:, 2].max())}, "
      f"{nc} not converged; peak probe pressure {p.max()/1e6:.2f} MPa")
sys.exit(check.exitStatus())
