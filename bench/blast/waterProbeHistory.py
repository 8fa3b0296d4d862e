#!/usr/bin/env python3
"""The water probes' pressure history of a blast case beside its two 1D
answers (issue 17 item 1; not a test): the scene (postProcessing/
fluidProbes), the layered column (postProcessing/planeWaveLayered/0/
reference.dat, planeWave -layered) and the water-only column
(postProcessing/planeWave/0/reference.dat, planeWave; each if the case
has it), every STEP from
T0 to T1, and the largest 1-ns running mean of each with its time.

Usage: waterProbeHistory.py CASE [T0 T1 STEP]   (default 58e-9 95e-9
1e-9 s; run planeWave -case CASE and planeWave -case CASE -layered first)
"""
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
from neuronFsi import planeWave as pw


def main():
    case = sys.argv[1]
    t0, t1, dt = ((float(x) for x in sys.argv[2:5]) if len(sys.argv) > 4
                  else (58e-9, 95e-9, 1e-9))
    # the references the case has (each planeWave run writes its own)
    refs = [(name, pw.readReference(path)) for name, path in (
        (name, os.path.join(case, "postProcessing", d, "0",
                            "reference.dat"))
        for name, d in (("layered", "planeWaveLayered"),
                        ("water only", "planeWave")))
        if os.path.isfile(path)]
    for n, z, t, p in pw.caseProbes(case, solid=False):
        print("%s at z = %g um: largest 1-ns mean [MPa] at [ns]" % (n, z*1e6))
        rows = [("scene", t, p)] + [(name, r.t, r.at(z)) for name, r in refs]
        for name, tt, pp in rows:
            tc, m = pw.runningMean(tt, pp, 1e-9)
            k = int(np.argmax(m))
            print("  %s: %.3f at %.2f" % (name, m[k]*1e-6, tc[k]*1e9))
        print("| t [ns] | " + " | ".join(r[0] + " [MPa]" for r in rows)
              + " |")
        print("|---:|" + "---:|"*len(rows))
        for tt in np.arange(t0, t1 + 0.5*dt, dt):
            print("| %.2f | %s |" % (tt*1e9, " | ".join(
                "%.2f" % (np.interp(tt, a, b)*1e-6) for _, a, b in rows)))


if __name__ == "__main__":
    main()
