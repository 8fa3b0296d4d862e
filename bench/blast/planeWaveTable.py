#!/usr/bin/python3
"""The exact 1D answer of a blast case over the cell's height, as the
table that planeWaveCell -table reads (issue 17 item 6; docs/results/
blast3D.md, "The von Mises at rest in 3D"); not a test.

The case's own 1D column (neuronFsi.planeWave.column: rhoRiemannFoam on
the case's water law and pulse, the whole physical column) probed at
heights 0, dzProbe, ... up to --top; written as text:

    # comment lines
    nz nt
    z_1 ... z_nz                       [m]
    t p(z_1) ... p(z_nz) u(z_1) ... u(z_nz)   (nt rows; s, Pa, m/s; u
                                              positive upwards)

    bench/blast/planeWaveTable.py CASE OUT [--top 8.4e-6] [--dzProbe
        50e-9] [--dz 25e-9] [--endTime the case's]

CASE: a prepared tutorials/blast case (Allrun -noRun: 0/, constant/).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "src", "python"))
from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import foamDict, planeWave as pw  # noqa: E402


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("case")
    a.add_argument("out")
    a.add_argument("--top", type=float, default=8.4e-6)
    a.add_argument("--dzProbe", type=float, default=50e-9)
    a.add_argument("--dz", type=float, default=25e-9)
    a.add_argument("--endTime", type=float, default=None)
    o = a.parse_args()
    case = os.path.abspath(o.case)
    end = o.endTime
    if end is None:
        end = float(foamDict.read(os.path.join(case, "system",
                                               "controlDict"))["endTime"])
    n = int(round(o.top/o.dzProbe))
    heights = [k*o.dzProbe for k in range(n + 1)]
    Z = pw.caseColumnHeight(case)
    w = pw.column(case, heights, Z, end, dz=o.dz)
    with open(o.out, "w") as f:
        f.write("# 1D answer of %s: column %g m, cells %g m, to %g s "
                "(bench/blast/planeWaveTable.py)\n" % (case, Z, o.dz, end))
        f.write("%d %d\n" % (len(heights), len(w.t)))
        f.write(" ".join("%.10g" % z for z in heights) + "\n")
        for k in range(len(w.t)):
            f.write("%.12g %s %s\n" % (
                w.t[k], " ".join("%.9g" % v for v in w.p[k]),
                " ".join("%.9g" % v for v in w.u[k])))
    print("%s: %d heights to %g m, %d times to %g s; peak p %.4g Pa, "
          "peak |u| %.4g m/s" % (o.out, len(heights), heights[-1], len(w.t),
                                 w.t[-1], w.p.max(), abs(w.u).max()))


if __name__ == "__main__":
    main()
