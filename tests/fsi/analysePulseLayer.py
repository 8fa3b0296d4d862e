#!/usr/bin/python3
"""Measures of a pulseLayer run (50 MPa, 5 ns pulse in water crossing into
a solid layer with water's EOS on a rigid wall):
 - reflection: largest |p| in the fluid probe (x = 25 um) after the
   incident pulse has passed it (t > 30 ns) and before the wall echo can
   return (t < 100 ns), in % of the 50 MPa incident amplitude;
 - arrival: first time the solid probe at x = 75 um exceeds 25 MPa [ns];
 - wall: peak pressure of the solid element at the wall [MPa];
 - coupling: steps, mean/max iterations, non-converged steps.
Usage: analysePulseLayer.py <case>   (prints one line of key=value)"""
import sys
import numpy as np

case = sys.argv[1]
fp = np.loadtxt(f"{case}/postProcessing/probes/0/p", comments="#")
sp = np.loadtxt(f"{case}/postProcessing/solidProbes/0/solidProbes.dat",
                comments="#")
cp = np.loadtxt(f"{case}/postProcessing/fsi/0/coupling.dat", comments="#")

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

it = cp[:, 2]
print(f"reflection={reflection:.3f}% arrival={arrival:.3f}ns "
      f"wall={wall:.2f}MPa incident75={incident:.2f}MPa "
      f"steps={len(it)} meanIter={it.mean():.2f} maxIter={int(it.max())} "
      f"nonConverged={int(np.sum(cp[:, 4] == 0))} "
      f"maxResidual={cp[:, 3].max():.2e} maxGcl={cp[:, -1].max():.1e}")
