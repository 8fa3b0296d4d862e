#!/usr/bin/python3
"""Assertions on a run of tutorials/blast/axisymmetricPreview (smoke.sh):
map check, arrival time at the probe, coupling convergence.
usage: checkPreview.py case Z"""
import math
import re
import sys
import numpy as np

from neuronFsi import logs, postProcessing

case, Z = sys.argv[1], float(sys.argv[2])
a, H = 8.4e-6, 7.9e-6
ok = True


def check(name, value, ref, tol):
    global ok
    err = abs(value - ref)/abs(ref)
    good = err <= tol
    ok &= good
    print(f"{'ok  ' if good else 'FAIL'} {name}: {value:.10g} vs {ref:.10g}"
          f" (relative {err:.2e}, tolerance {tol:g})")


(fr, fz, _), (sr, sz, _) = logs.fsiMapCheck(f"{case}/log.cellBlastFoam")
check("map conservation, radial", sr, fr, 1e-12)
check("map conservation, axial", sz, fz, 1e-12)
check("axial ring force = -pi a^2", fz, -math.pi*a*a, 1e-9)
check("radial ring force ~ -pi^2 a H/2", fr, -math.pi**2*a*H/2, 1e-3)

# Arrival at the probe (its reference point from the header)
log = "solidProbes/solidProbes.dat"
zc = None
for line in postProcessing.header(case, log):
    if line.startswith("probe 0"):
        zc = float(re.search(r" at \(\S+ (\S+) \S+\) m", line).group(1))
d = postProcessing.series(case, log)
t, p = d[:, 0], d[:, 1]
rho0, C0, s, pulse = 1000.0, 1450.0, 1.99, 50e6
up = (-C0 + math.sqrt(C0**2 + 4*s*pulse/rho0))/(2*s)
Us = C0 + s*up
# Arrival: the front's mid-point, p > half of the probe's own peak (the
# coarse far column of the smoke run lowers the peak of the 5 ns pulse)
if p.max() < 0.5*pulse:
    print(f"FAIL the pulse reached the probe with {p.max()/1e6:.3g} MPa only")
    sys.exit(1)
arrival = t[np.argmax(p > p.max()/2)]
check(f"arrival at the probe (z = {zc*1e6:.3f} um, Us = {Us:.2f} m/s) [s]",
      arrival, 0.05e-9 + (Z - zc)/Us, 0.03)

c = postProcessing.series(case, "fsi/coupling.dat")
nc = int(np.sum(c[:, 4] == 0))
print(f"{'ok  ' if nc == 0 else 'FAIL'} coupling: {len(c)} steps, "
      f"iterations mean {c[:, 2].mean():.2f} max {int(c[:, 2].max())}, "
      f"{nc} not converged; peak probe pressure {p.max()/1e6:.2f} MPa")
ok &= nc == 0
sys.exit(0 if ok else 1)
