#!/usr/bin/python3
"""The exact plane-wave traction for bench/solid/exactTraction (the
preview's cell alone, no water; issue 17 item 4; docs/results/
blastPlaneWave.md, "The solid alone under the exact traction"; not a
test).

Usage: exactTraction.py CASE OUT [-dz 10e-9] [-spacing 25e-9]
                        [-endTime 9e-8] [-probes FILE] [-top H]

CASE: a prepared axisymmetric preview (tests/blast/runPreview.sh DIR
-noRun, or a run of it: its constant/cell.msh, constant/
thermophysicalProperties, 0/p's pulse, constant/solidProperties). The 1D
answer is the project's Lagrangian water column (neuronFsi.layeredColumn,
von Neumann-Richtmyer, verified against rhoRiemannFoam and the exact wall
collision; water only: the transparent cell's exact answer) of the case's
column height with its pulse, cells of -dz (default 10 nm: 14 times finer
than the finest solid face of the ladder, G's 0.14 um membrane faces),
recorded every 4 steps (about 11 ps at 10 nm). Writes in OUT:

  table.dat  p_1D(Z, t) [Pa]: the column's pressure p + q at the material
      points of reference heights Z = 0, -spacing, ... up to the cell's
      top (cell.msh's largest z, or -top H [m] for a case without it: the
      tutorial's inputs and a block of the driver) and one more, from 1 ns before the wave
      reaches the top (the first record with |p| > 1 kPa there) to
      -endTime; the driver's TABLE.
  probes  the probes of CASE's postProcessing/solidProbes (a run's header:
      the same points, the interface probe's as the scene placed it) or of
      -probes FILE (NAME REGION r z [R] per line); the driver's -probes.
  postProcessing/planeWave/0/reference.dat  the same column at the probes'
      material points (planeWave.writeReference; pM_z, rhoM_z, TM_z), and
      constant/solidProperties(.allrun) copied from CASE: so that
      bench/blast/ballLadder.py reads OUT as it reads a scene run.

Then:
  build/bin/exactTraction CASE/constant/cell.msh OUT/table.dat OUT \\
      -probes OUT/probes
  bench/blast/ballLadder.py H=OUT ...
"""
import math
import os
import shutil
import sys

import numpy as np

from neuronFsi import layeredColumn, msh, planeWave, postProcessing, script

KEEP = 4    # record every KEEP column steps


def option(args, name, default):
    if name in args:
        k = args.index(name)
        if k + 1 >= len(args):
            sys.exit("exactTraction.py: %s needs a value" % name)
        value = args[k + 1]
        del args[k:k + 2]
        try:
            x = float(value)
        except ValueError:
            sys.exit("exactTraction.py: %s %s is not a number"
                     % (name, value))
        if not (math.isfinite(x) and x > 0):
            sys.exit("exactTraction.py: %s %s: must be positive and finite"
                     % (name, value))
        return x
    return default


def readProbes(path):
    out = []
    with open(path) as f:
        for n, line in enumerate(f, 1):
            w = line.split("#")[0].split()
            if not w:
                continue
            if len(w) not in (4, 5):
                sys.exit("exactTraction.py: %s:%d: a probe is NAME REGION r "
                         "z [R]" % (path, n))
            try:
                r, z = float(w[2]), float(w[3])
                R = float(w[4]) if len(w) == 5 else 0.0
            except ValueError:
                sys.exit("exactTraction.py: %s:%d: r, z, R must be numbers"
                         % (path, n))
            out.append((w[0], w[1], r, z, R))
    return out


def main():
    args = sys.argv[1:]
    dz = option(args, "-dz", 10e-9)
    spacing = option(args, "-spacing", 25e-9)
    endTime = option(args, "-endTime", 9e-8)
    top = option(args, "-top", None)
    probesFile = None
    if "-probes" in args:
        k = args.index("-probes")
        if k + 1 >= len(args):
            sys.exit("exactTraction.py: -probes needs a file")
        probesFile = args[k + 1]
        del args[k:k + 2]
    if len(args) != 2:
        sys.exit(__doc__)
    case, out = args
    if not os.path.isdir(os.path.join(case, "constant")):
        case = os.path.join(case, "axisymmetricPreview")
    if top is None:
        X, _ = msh.read(os.path.join(case, "constant", "cell.msh"))
        zTop = max(x[1] for x in X.values())
    else:
        zTop = top
    Z = planeWave.caseColumnHeight(case)
    if probesFile:
        probes = readProbes(probesFile)
    else:
        probes = [(q["name"], q["region"], q["point"][0], q["point"][1],
                   q["radius"])
                  for q in postProcessing.probes(case)]
    n = int(math.ceil(zTop/spacing)) + 1
    grid = [k*spacing for k in range(n + 1)]
    heights = sorted(set(grid) | {q[3] for q in probes})

    law = layeredColumn.waterLaw(case)
    col = layeredColumn.Column([], law, Z, dz)
    pulse = planeWave.appliedPressure(case)
    t, P, RHO, U, T, _ = col.run(pulse, endTime, (), heights, every=KEEP)
    amp = max(abs(v) for _, v in pulse)
    top = heights.index(grid[-1])
    k0 = int(np.argmax(np.abs(P[:, top]) > 1e3))
    if not np.abs(P[k0, top]) > 1e3:
        sys.exit("exactTraction.py: the wave does not reach the cell's top "
                 "(%g m) by %g s" % (zTop, endTime))
    k0 = int(np.searchsorted(t, t[k0] - 1e-9))
    os.makedirs(out, exist_ok=True)
    cols = [heights.index(z) for z in grid]
    with script.writing(os.path.join(out, "table.dat")) as f:
        f.write("# p_1D(Z, t) [Pa] at the material points of reference "
                "height Z: neuronFsi.layeredColumn's water column of %s "
                "(height %g m, cells of %g m, pulse of %g Pa), every %d "
                "steps from %.6g s\n" % (case, Z, dz, amp, KEEP, t[k0]))
        f.write("# Z [m] %s\n" % " ".join("%.9g" % z for z in grid))
        for k in range(k0, len(t)):
            f.write("%.12g %s\n" % (t[k], " ".join(
                "%.9g" % v for v in P[k, cols])))
    with script.writing(os.path.join(out, "probes")) as f:
        f.write("# NAME REGION r z [R] [m] (from %s)\n"
                % (probesFile or case))
        for name, region, r, z, R in probes:
            f.write("%s %s %.10g %.10g %.10g\n" % (name, region, r, z, R))
    ph = sorted({q[3] for q in probes})
    idx = [heights.index(z) for z in ph]
    wave = planeWave.PlaneWave(ph, t, P[:, idx], dz, Z, RHO[:, idx],
                               U[:, idx], T[:, idx])
    for z, i in zip(ph, idx):
        wave.material[z] = {"p": P[:, i], "rho": RHO[:, i], "T": T[:, i],
                            "z": None}
    ref = os.path.join(out, "postProcessing", "planeWave", "0")
    os.makedirs(ref, exist_ok=True)
    planeWave.writeReference(
        os.path.join(ref, "reference.dat"), wave,
        "exactTraction.py: neuronFsi.layeredColumn water column, cells of "
        "%g m, at the solid probes' material points" % dz)
    os.makedirs(os.path.join(out, "constant"), exist_ok=True)
    for name in ("solidProperties", "solidProperties.allrun"):
        src = os.path.join(case, "constant", name)
        if os.path.exists(src):
            shutil.copy(src, os.path.join(out, "constant", name))
    print("exactTraction.py: %s: %d heights to %.4g m (cell top %.4g m), "
          "%d times %.6g to %.6g s, %d column cells of %g m; %d probes"
          % (out, len(grid), grid[-1], zTop, len(t) - k0, t[k0], t[-1],
             col.N, dz, len(probes)))


if __name__ == "__main__":
    script.guard()  # an input's error: one line, exit 1
    main()
