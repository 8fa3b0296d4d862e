#!/usr/bin/python3
"""The scene's own numbers of two blast runs side by side (issue 17 item 4,
the 3D sentence: "the axis probes within 10 % of the preview"; not a
test): for each pair of probes named, the measures planeWave wrote into
each case (postProcessing/planeWave/0/measures.dat: arrival, 1-ns peak,
incident 1-ns peak, plateau, impulse; solidMeasures.dat: von Mises and
strain 1-ns peaks), the first run's value, the second's, and the first
against the second (arrival: the difference in ns; the others: the
relative difference in %). Run planeWave in both cases first (the
tutorial's plots stage, or `planeWave -case CASE -dz 50e-9`).

    bench/blast/sceneAgainstPreview.py CASE3D CASE2D PAIR... [--bound 10]

PAIR: NAME3D=NAME2D, the probes' names in measures.dat (fluidProbes_<i>,
solid_p<i>) or solidMeasures.dat (solid_<i>), e.g. for the quarter
against the preview: fluidProbes_1=fluidProbes_0 (the axis at z = 10 um)
solid_p0=solid_p0 solid_p1=solid_p1 (the Fig. 10 point, cytoplasm /
nucleus side) solid_0=solid_0 solid_1=solid_1. Prints markdown; a
relative difference above --bound [%] (default 10) is in bold.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "src", "python"))
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import planeWave as pw  # noqa: E402

PRESSURE = [("arrival", "arrival [ns]", 1.0),
            ("peak1ns", "1-ns peak [MPa]", 1.0),
            ("peakIncident", "incident 1-ns peak [MPa]", 1.0),
            ("plateau", "plateau [MPa]", 1.0),
            ("impulse", "impulse [Pa s]", 1.0)]
SOLID = [("vonMises1ns", "von Mises 1-ns peak [Pa]", 1.0),
         ("strain1ns", "strain_z 1-ns peak [-]", 1.0)]


def rows(case, name):
    path = os.path.join(case, "postProcessing", "planeWave", "0", name)
    if not os.path.isfile(path):
        sys.exit("sceneAgainstPreview.py: %s not found: run planeWave in "
                 "%s first" % (path, case))
    return {r["probe"]: r for r in pw.readMeasures(path)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case3D")
    ap.add_argument("case2D")
    ap.add_argument("pairs", nargs="+", metavar="NAME3D=NAME2D")
    ap.add_argument("--bound", type=float, default=10.0)
    a = ap.parse_args()
    if not a.bound > 0:
        sys.exit("sceneAgainstPreview.py: --bound %g: must be > 0 [%%]"
                 % a.bound)
    m = [rows(c, "measures.dat") for c in (a.case3D, a.case2D)]
    s = [rows(c, "solidMeasures.dat") for c in (a.case3D, a.case2D)]
    chosen = []
    for pair in a.pairs:
        if pair.count("=") != 1:
            sys.exit("sceneAgainstPreview.py: %s: give NAME3D=NAME2D"
                     % pair)
        n3, n2 = pair.split("=")
        if n3 in m[0] and n2 in m[1]:
            chosen.append((n3, n2, m[0][n3], m[1][n2], PRESSURE))
        elif n3 in s[0] and n2 in s[1]:
            chosen.append((n3, n2, s[0][n3], s[1][n2], SOLID))
        else:
            sys.exit("sceneAgainstPreview.py: %s: no such probe pair in "
                     "both cases' measures (first: %s; second: %s)"
                     % (pair, ", ".join(list(m[0]) + list(s[0])),
                        ", ".join(list(m[1]) + list(s[1]))))
    print("| probe (first / second run) | measure | first | second "
          "| first against second |")
    print("|---|---|---:|---:|---:|")
    worst = 0.0
    for n3, n2, r3, r2, cols in chosen:
        for key, label, _ in cols:
            v3, v2 = r3[key], r2[key]
            if key == "arrival":
                d = "%+.2f ns" % (v3 - v2)
            else:
                rel = 100.0*(v3 - v2)/abs(v2)
                worst = max(worst, abs(rel))
                d = "%+.1f %%" % rel
                if abs(rel) > a.bound:
                    d = "**%s**" % d
            print("| %s / %s | %s | %.5g | %.5g | %s |"
                  % (n3, n2, label, v3, v2, d))
    print("\nlargest relative difference: %.1f %% (bound %g %%)"
          % (worst, a.bound))


if __name__ == "__main__":
    main()
