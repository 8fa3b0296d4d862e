#!/usr/bin/python3
"""After the pulse: the probe (pressure, von Mises, strain_z) at 90-150 ns,
the largest interface velocity after 110 ns and at the end, and the
coupling passes per step over 0-55 / 55-90 / 90-110 / 110-150 ns of a
blast case. The logs of every start of a restarted run are joined (a
restart writes postProcessing/<log>/<start time>/).
usage: late.py CASE"""
import sys
import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(1, "CASE")
from neuronFsi.postProcessing import series

case = sys.argv[1]

p = series(case, 'solidProbes/solidProbes.dat')
base = 1 + 5*((p.shape[1] - 1)//7)         # strain_z column of probe 0
for T in (90, 100, 110, 120, 130, 140, 150):
    i = np.argmin(abs(p[:, 0] - T*1e-9))
    print(f"t {p[i, 0]*1e9:.1f} ns: probe p {p[i, 1]/1e6:.3f} MPa, von Mises "
          f"{p[i, 2]:.2f} Pa, strain_z {p[i, base]:.4f}")
c = series(case, 'fsi/coupling.dat')
w = c[:, 0] > 110e-9
if not w.any():
    sys.exit("late.py: error: %s: no coupling rows after 110 ns (the run "
             "ends at %.3g ns)" % (case, c[-1, 0]*1e9))
print(f"interface velocity: max after 110 ns {c[w, 8].max():.3g} m/s, at the "
      f"end {c[-1, 8]:.3g} m/s")
print("coupling passes per step: " + ", ".join(
    f"{a}-{b} ns {c[(c[:, 0] > a*1e-9) & (c[:, 0] <= b*1e-9), 2].mean():.2f}"
    for a, b in ((0, 55), (55, 90), (90, 110), (110, 150))))
