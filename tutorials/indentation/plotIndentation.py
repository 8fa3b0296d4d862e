#!/usr/bin/python3
"""Plots and results table of a cellIndentationFoam case.

usage: plotIndentation.py [-acceptHandMade] <case> [<case> ...]

force.dat and peaks.dat must be as cellIndentationFoam wrote them (their
digests, force.dat.fnv1a64 and peaks.dat.fnv1a64 beside them); a file made
or edited by hand is refused naming its first changed line, unless
-acceptHandMade.

Reads <case>/postProcessing/indentation/{force,peaks}.dat and writes
<case>/indentation.png (force vs depth for each rate, like the paper's
Figs. 4-6, and force vs time) and <case>/results.md (the nine cycle peaks
next to the paper's Table 3, whose "mN" are nN, and F at the end of B and
on the E plateau next to the paper's 0.3 nN and 1.67 nN).
"""
import os
import sys

try:
    from neuronFsi import script
except ImportError:
    sys.exit("plotIndentation.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import indentationPlots as ip
from neuronFsi import resultDigest
from neuronFsi.paper import TABLE3_EXP as PAPER_EXP, TABLE3_SIM as PAPER_SIM
from neuronFsi.paper import F_B as PAPER_FB, F_E as PAPER_FE


def table(case, peaks):
    labels = [f"C{a},{b}" for a in (1, 2, 3) for b in ("i", "ii", "iii")]
    out = ["| quantity | this run [nN] | paper exp. [nN] | paper sim. [nN] |",
           "|---|---|---|---|"] if "validation" in os.path.abspath(case) else \
          ["| quantity | this run [nN] | paper exp., validation cell [nN] "
           "| paper sim., validation cell [nN] |",
           "|---|---|---|---|"]
    for k, label in enumerate(labels):
        F = peaks.get(label, (0, 0, float("nan")))[2]*1e9
        out.append(f"| {label} | {F:.3g} | {PAPER_EXP[k]} | {PAPER_SIM[k]} |")
    FB = peaks.get("endB", (0, 0, float("nan")))[2]*1e9
    FE = peaks.get("endE", (0, 0, float("nan")))[2]*1e9
    out.append(f"| F_B (end of B) | {FB:.3g} | {PAPER_FB} (average cell) | |")
    out.append(f"| F_E (end of E) | {FE:.3g} | {PAPER_FE} (average cell) | |")
    text = "\n".join(out) + "\n"
    with script.writing(os.path.join(case, "results.md")) as f:
        f.write(text)
    print(text)


cases = [c for c in sys.argv[1:] if c != "-acceptHandMade"]
resultDigest.measuring("-acceptHandMade", len(cases) < len(sys.argv[1:]))
for case in cases or ["."]:
    try:
        rows, peaks = ip.read(case)
    except ip.IndentationPlotError as err:
        sys.exit("plotIndentation.py: error: %s" % err)
    ip.forceDepth(case, rows, os.path.join(case, "indentation.png"))
    table(case, peaks)
