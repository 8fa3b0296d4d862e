#!/usr/bin/python3
"""The 3D quarter's water mesh by face non-orthogonality (issue 17 item 6;
docs/results/blast3D.md, "An O-grid without the kink"); not a test.

    bench/blast/ogridQuality.py CASE [CASE ...]

CASE: a prepared tutorials/blast/quarter3D case (constant/polyMesh of the
water, e.g. `./Allrun -noRun` or a bench/blast/restVariants3D.sh case).
Per case, from a scratch copy (the case is not written to): checkMesh's
largest and mean face non-orthogonality and largest skewness, then per
cell its largest face non-orthogonality (checkMesh -writeFields
nonOrthoAngle) and centre (postProcess writeCellCentres):
  - the cell count in the bands 20-30, 30-40, 40 deg and more, and the
    volume fraction (the water's mass fraction at rest) from 20, 30 and
    40 deg on (postProcess writeCellVolumes);
  - the same over the cells whose centre is above the cell's top
    (z > 7.9 um), which the plane pulse crosses before it reaches the
    cell, and above 6 um, with their largest;
  - the five worst cells with their centre [um], and the three most
    skewed (checkMesh -writeFields skewness).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import foamField as ff

H = 7.9e-6  # [m] the cell's height (tutorials/blast/quarter3D)


def quality(case):
    tmp = tempfile.mkdtemp()
    try:
        for s in ("constant", "system"):
            shutil.copytree(os.path.join(case, s), os.path.join(tmp, s))
        os.makedirs(os.path.join(tmp, "0"))
        p = subprocess.run(["checkMesh", "-case", tmp, "-constant",
                            "-writeFields", "(nonOrthoAngle skewness)"], check=True,
                           capture_output=True, text=True)
        subprocess.run(["postProcess", "-case", tmp, "-time", "0", "-funcs",
                        "(writeCellCentres writeCellVolumes)"], check=True,
                       capture_output=True)
        no = ff.internalField(os.path.join(tmp, "constant", "nonOrthoAngle"))
        sk = ff.internalField(os.path.join(tmp, "constant", "skewness"))
        C = ff.internalField(os.path.join(tmp, "0", "C"))
        V = ff.internalField(os.path.join(tmp, "0", "V"))
    finally:
        shutil.rmtree(tmp)
    m = re.search(r"non-orthogonality Max: ([-+.eE\d]+) average: ([-+.eE\d]+)",
                  p.stdout)
    skew = re.search(r"Max skewness = ([-+.eE\d]+)", p.stdout).group(1)
    print("%s: %d cells; checkMesh: non-orthogonality max %.1f deg, mean "
          "%.2f deg, skewness max %.3f" % (case, len(no), float(m.group(1)),
                                           float(m.group(2)), float(skew)))

    def bands(s):
        return ", ".join("%d-%s deg %d" % (lo, hi or "", ((no >= lo) & (
            no < (hi or 180)) & s).sum()) for lo, hi in ((20, 30), (30, 40),
                                                       (40, None)))
    print("   cells by their largest face non-orthogonality: %s"
          % bands(np.ones(len(no), bool)))
    print("   volume (the water's mass at rest) in cells of 20 deg or more"
          " %.2f %%, 30 deg or more %.2f %%, 40 deg or more %.2f %%"
          % tuple(100*V[no >= lo].sum()/V.sum() for lo in (20, 30, 40)))
    for z in (H, 6e-6):
        s = C[:, 2] > z
        print("   above z = %.1f um (%d cells): largest %.1f deg; %s"
              % (z*1e6, s.sum(), no[s].max(), bands(s)))
    for i in np.argsort(-no)[:5]:
        print("   %.1f deg at (%.2f, %.2f, %.2f) um" % (no[i], *(C[i]*1e6)))
    for i in np.argsort(-sk)[:3]:
        print("   skewness %.3f at (%.2f, %.2f, %.2f) um" % (sk[i],
                                                           *(C[i]*1e6)))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for case in sys.argv[1:]:
        quality(case)


if __name__ == "__main__":
    main()
