#!/usr/bin/python3
"""Assertions on a 150 ns run of tutorials/blast/axisymmetricPreview
(longRun.sh): the run reached its end time with every coupling step
converged and no element failure, the pulse reached the probe, and the
cell is at rest again after the pulse: no node drifts. Before the hourglass
viscosity (docs/results/blast.md) membrane nodes kept 7-8 m/s from 80 ns on
and an element failed at 132 ns.
usage: checkLongRun.py case endTime"""
import math
import os
import sys
import numpy as np

from neuronFsi import logs, postProcessing, script
from neuronFsi.checks import Checks
from neuronFsi.solidResults import SolidResults

# an input's error (a missing or damaged file, a wrong argument) is one
# line naming it, exit 1, not a traceback (adv51 m06)
script.guard()
if len(sys.argv) != 3:
    sys.exit("checkLongRun.py: error: usage: checkLongRun.py case endTime")
case = sys.argv[1]
try:
    endTime = float(sys.argv[2])
except ValueError:
    endTime = math.nan
if not (math.isfinite(endTime) and endTime > 0):
    sys.exit("checkLongRun.py: error: endTime '%s' is not a number of "
             "seconds in (0, inf)" % sys.argv[2])
if not os.path.isdir(case):
    sys.exit("checkLongRun.py: error: the case %s is not a folder" % case)
check = Checks()


log = f"{case}/log.cellBlastFoam"
done = logs.completed(log)
check(done, "run completed: "
      + ("log ends with End" if done else "no End in the log, or FATAL"))
coupling = postProcessing.series(case, "fsi/coupling.dat")
# OpenFOAM's own criterion: the run ends within half a step of endTime
check(coupling[-1, 0] >= endTime - 0.5*coupling[-1, 1],
      f"end time reached: last step at {coupling[-1, 0]:.6g} s (dt "
      f"{coupling[-1, 1]:.3g} s) of {endTime:g} s")
try:
    m = logs.couplingSummary(log)
except logs.LogError:
    m = None
check(m and m["notConverged"] == 0, "coupling converged every step: "
      + (m["line"] if m else "no coupling summary"))

probes = postProcessing.series(case, "solidProbes/solidProbes.dat")
check(probes[:, 1].max() > 25e6, "pulse reached the probe: peak pressure "
      f"{probes[:, 1].max()/1e6:.4g} MPa")

# Rest after the pulse: particle velocity of the 50 MPa pulse in water is
# 33 m/s; once it has left (t >= 110 ns) no node may keep 10 % of it
up = 33.0
if not os.path.isfile(f"{case}/solid/solid.h5"):
    sys.exit(f"checkLongRun.py: error: {case}/solid/solid.h5 does not "
             "exist: no solid results to check (the run wrote none, or "
             "they were moved)")
with SolidResults(f"{case}/solid/solid.h5") as f:
    steps = f.steps()
    times = np.array(f.times())
    late = [k for k, t in zip(steps, times) if t >= 110e-9]
    # a cut, restarted or running case may have no write from 110 ns, or
    # none at all: said as a failed check, the others still made (adv50b
    # k18, k19, k53: "max() arg is an empty sequence", a traceback)
    vmax = max((np.abs(f.field(k, "velocity")).max() for k in late),
               default=None)
    Jmin = min((f.field(k, "J").min() for k in steps), default=None)
    Jmax = max((f.field(k, "J").max() for k in steps), default=None)
if vmax is None:
    check(False, "no rest state: the run has no write at or after 110 ns "
          "(last write at %s)" % ("%.4g s" % times[-1] if len(times)
                                  else "none"))
else:
    check(vmax < 0.1*up, "no drift after the pulse: largest nodal speed "
          f"component from 110 ns {vmax:.3g} m/s (< {0.1*up:.3g} m/s) over "
          f"{len(late)} writes")
if Jmin is None:
    check(False, "elements stay sound: solid.h5 has no step")
else:
    check(Jmin > 0.9 and Jmax < 1.1, "elements stay sound: element "
          f"dilatation J in [{Jmin:.4f}, {Jmax:.4f}]")
sys.exit(check.exitStatus())
