#!/usr/bin/env python3
"""The solid probes' longitudinal strain split into its volumetric part
and the lateral remainder, for blast cases (issue 17 item 4: why the
probe's von Mises and strain scatter over the mesh ladder; not a test).

In a plane wave through an acoustically transparent cell the deformation
is uniaxial: ln(stretch_z) = ln J, no lateral strain. The pressure sets J
through the volumetric law; the split of J between the axis and the
lateral directions is isochoric, held only by the shear moduli (1e2 Pa
against the bulk's 2e9 Pa), so a numerical lateral motion stays. Per
probe of each case: the 1-ns peaks (largest |1-ns running mean|) of ln J
and of ln(stretch_z), and the lateral strain ln J - ln(stretch_z) at the
instant of the ln(stretch_z) peak; with the uniaxial answer of planeWave
-check (postProcessing/planeWave/0/solidMeasures.dat, strain1nsRef) when
the case has one.

Usage: strainSplit.py CASE...   (cases run by tests/blast/runPreview.sh
and checked by planeWave -case CASE -check)
"""
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
from neuronFsi import planeWave, postProcessing

LOG = "solidProbes/solidProbes.dat"


def peak1ns(t, y):
    """(largest |1-ns running mean|, its instant [s])."""
    tc, m = planeWave.runningMean(t, y, 1e-9)
    i = int(np.argmax(np.abs(m)))
    return m[i], tc[i], (tc, m)


def main(cases):
    print("# case  probe  lnJ1ns[-]  lnZ1ns[-]  lateralAtPeak[-]  "
          "tPeak[ns]  uniaxialRef[-]")
    for case in cases:
        data = postProcessing.series(case, LOG)
        postProcessing.checkCovers(case, LOG, data)
        cols = postProcessing.names(case, LOG)
        ref = solidRefs(case)
        t = data[:, 0]
        for i, _ in enumerate(postProcessing.probes(case, LOG)):
            lnJ = data[:, cols.index("strain%d" % i)]
            lnZ = data[:, cols.index("strainZ%d" % i)]
            j, _, _ = peak1ns(t, lnJ)
            z, tz, _ = peak1ns(t, lnZ)
            _, mJ = planeWave.runningMean(t, lnJ, 1e-9)
            tc, mZ = planeWave.runningMean(t, lnZ, 1e-9)
            k = int(np.argmin(np.abs(tc - tz)))
            print("%s  %d  %.5f  %.5f  %+.5f  %.2f  %s"
                  % (case, i, j, z, mJ[k] - mZ[k], tz*1e9,
                     "%.5f" % ref[i] if i in ref else "-"))


def solidRefs(case):
    """{probe index: the uniaxial answer's 1-ns strain peak} from
    planeWave -check's solidMeasures.dat (empty when it is not there)."""
    path = os.path.join(case, "postProcessing", "planeWave", "0",
                        "solidMeasures.dat")
    if not os.path.isfile(path):
        return {}
    return {int(r["probe"][len("solid_"):]): r["strain1nsRef"]
            for r in planeWave.readMeasures(path)}


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
