#!/usr/bin/python3
"""Transmitted and reflected amplitudes of a weak pulse (linear acoustics)
crossing from water into a solid layer of another acoustic impedance: a
run of the pulseLayer case (tests/fsi/pulseLayer) with the pulse amplitude
pI, the solid density rho0s and sound speed C0s (impedanceRun.sh).

Each amplitude is the mean over 1 ns at the centre of the pulse's plateau
where the probe sees it (pulse: 0.1 ns ramps, plateau to 5 ns, centre of
the table at 2.55 ns; water C0 = 1450 m/s from x = 0 to the interface at
50 um, the solid's C0s from 50 um to the rigid wall at 100 um):
 - incident: fluid probe at 25 um, centre 2.55 ns + 25 um/C0;
 - reflected: fluid probe at 25 um, centre 2.55 ns + 75 um/C0 (the
   reflected pulse alone: the incident one has passed, the wall echo
   arrives after 2.55 ns + 25 um/C0 + 100 um/C0s + 50 um/C0);
 - interface: x force of the coupling log over the 1 um^2 cross-section,
   centre 2.55 ns + 50 um/C0 (the transmitted wave at the interface);
 - transmitted: solid probe at 75 um, centre 2.55 ns + 50 um/C0 + 25 um/C0s.
Exact (linear acoustics, pressure amplitudes): T = 2 Z2/(Z1 + Z2),
R = (Z2 - Z1)/(Z1 + Z2), Z1 = 1000 kg/m^3 x 1450 m/s, Z2 = rho0s C0s.
Errors are in % of pI. Also: NaN in any output, coupling statistics.
Usage: impedanceAnalyse.py <case> <rho0s [kg/m^3]> <C0s [m/s]> <pI [Pa]>
(prints one line of key=value)"""
import math
import sys
import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi.postProcessing import series

case = sys.argv[1]
rho0s, C0s, pI = (float(a) for a in sys.argv[2:5])
rho0, C0 = 1000.0, 1450.0
Z1, Z2 = rho0*C0, rho0s*C0s
T, R = 2*Z2/(Z1 + Z2), (Z2 - Z1)/(Z1 + Z2)
tc = 2.55e-9

fp = series(case, "probes/p")
sp = series(case, "solidProbes/solidProbes.dat")
cp = series(case, "fsi/coupling.dat")
nan = int(not (np.isfinite(fp).all() and np.isfinite(sp).all()
               and np.isfinite(cp).all()))


def centre(t, v, t0):
    """Mean of v over [t0 - 0.5 ns, t0 + 0.5 ns]; nan if not reached."""
    m = (t > t0 - 0.5e-9) & (t < t0 + 0.5e-9)
    if not m.any() or t[-1] < t0 + 0.5e-9:
        return math.nan
    return float(np.mean(v[m]))


incident = centre(fp[:, 0], fp[:, 1], tc + 25e-6/C0)
reflected = centre(fp[:, 0], fp[:, 1], tc + 75e-6/C0)
interface = centre(cp[:, 0], cp[:, 5]/1e-12, tc + 50e-6/C0)
transmitted = centre(sp[:, 0], sp[:, 1], tc + 50e-6/C0 + 25e-6/C0s)
it = cp[:, 2]


def err(measured, exact):
    return 100*(measured - exact*pI)/pI


print(f"Zratio={Z2/Z1:.4g} T={T:.4f} R={R:.4f} "
      f"incident={incident/pI:.4f} reflected={reflected/pI:.4f} "
      f"interface={interface/pI:.4f} transmitted={transmitted/pI:.4f} "
      f"errIncident={err(incident, 1):.3f}% "
      f"errReflected={err(reflected, R):.3f}% "
      f"errInterface={err(interface, T):.3f}% "
      f"errTransmitted={err(transmitted, T):.3f}% "
      f"nan={nan} endTime={1e9*cp[-1, 0]:.2f}ns "
      f"steps={len(it)} meanIter={it.mean():.2f} maxIter={int(it.max())} "
      f"nonConverged={int(np.sum(cp[:, 4] == 0))}")
