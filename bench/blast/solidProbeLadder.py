#!/usr/bin/python3
"""The solid probes' von Mises and strain along a ladder of runs
(docs/results/blastPlaneWave.md, "The 5 ns von Mises"; not a test).

Usage: solidProbeLadder.py [-layered] H=DIR [H=DIR ...]

Each DIR a blast run (DIR/axisymmetricPreview, or DIR itself if it holds
postProcessing/) after `planeWave -case . -check` (with -layered: after
`planeWave -check -layered`), H its solid element size [m] (e.g. -cell).
Prints per probe (by its name in postProcessing/solidProbes: its region,
reference point) and run the 1-ns peaks of von Mises [Pa] and of the
longitudinal strain, the scene's and their errors against the reference
(solidMeasures.dat); then, per probe, from the three finest runs, the
observed order p and the Richardson limit of the scene's von Mises 1-ns
peak, v = v0 + C H^p (neuronFsi.convergence.threeLevel: Celik et al. 2008),
and that limit's error against the reference.
"""
import os
import sys

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
from neuronFsi import convergence, planeWave, postProcessing


def run(arg, layered):
    h, d = script.labelled(arg, "H=CASE")
    case = d if os.path.isdir(os.path.join(d, "postProcessing")) \
        else os.path.join(d, "axisymmetricPreview")
    sub = "planeWaveLayered" if layered else "planeWave"
    rows = planeWave.readMeasures(os.path.join(case, "postProcessing", sub,
                                               "0", "solidMeasures.dat"))
    probes = postProcessing.probes(case)
    out = {}
    for row in rows:
        i = int(row["probe"].split("_")[1])
        q = probes[i]
        out[q["name"]] = dict(row, point=q["point"])
    return float(h), out


def main():
    args = sys.argv[1:]
    layered = "-layered" in args
    args = [a for a in args if a != "-layered"]
    if not args:
        sys.exit(__doc__)
    runs = sorted((run(a, layered) for a in args), key=lambda x: -x[0])
    names = list(runs[0][1])
    print("| probe (region; r, z [um]) | H [um] | von Mises 1-ns peak "
          "[Pa]: scene / reference | error | strain 1-ns peak: scene / "
          "reference | error |")
    print("|---|---:|---:|---:|---:|---:|")
    for n in names:
        for h, out in runs:
            if n not in out:
                continue
            r = out[n]
            print("| %s (%s; %.3f, %.3f) | %g | %.4g / %.4g | %+.2f %% | "
                  "%.5g / %.5g | %+.2f %% |"
                  % (n, r["region"], r["point"][0]*1e6, r["point"][1]*1e6,
                     h*1e6, r["vonMises1ns"], r["vonMises1nsRef"],
                     r["errVonMises"], r["strain1ns"], r["strain1nsRef"],
                     r["errStrain"]))
    if len(runs) < 3:
        return
    print()
    print("| probe | runs (H [um]) | observed order p | Richardson limit "
          "of von Mises [Pa] | its error against the reference |")
    print("|---|---|---:|---:|---:|")
    for n in names:
        lv = [(h, out[n]) for h, out in runs if n in out][-3:]
        if len(lv) < 3:
            continue
        c = convergence.threeLevel([h for h, _ in lv],
                                   [r["vonMises1ns"] for _, r in lv])
        v0, p = c.extrapolated, c.p
        ref = lv[-1][1]["vonMises1nsRef"]
        print("| %s | %s | %s | %s | %s |"
              % (n, ", ".join("%g" % (h*1e6) for h, _ in lv),
                 "-" if p is None else "%.2f" % p,
                 "-" if v0 is None else "%.4g" % v0,
                 "-" if v0 is None else "%+.2f %%" % (100*(v0/ref - 1))))


if __name__ == "__main__":
    main()
