#!/usr/bin/python3
"""Blast scene plots and numbers (paper Fig. 10, Figs. 7-8 at 65.5 ns).

usage: plotBlast.py case [case ...] [-o prefix] [-label name ...]
                    [-until 1.5e-7] [-acceptHandMade] [-partial]
Probe peaks are taken over t <= until (default: the whole run), the
interface measures both over the window and over the run: the reported
one is the largest mean over a fixed length of interface (the solver's
interfacePatches.dat, interfacePatchLength of solidProperties), shown
with the element maxima (mesh-dependent). The logs are measured as their
run wrote them (their digests) and only when the run has ended: -partial
measures a run going on, or one stopped between its writes, so far;
-acceptHandMade measures files without (or against) their digests.

One case: <case>/fig10.png (pressure, von Mises, longitudinal strain and
strain rate at the probe on the cytoplasm-nucleus interface at 75 % of the
nucleus height), <case>/interfaceMaxima.png (the interface patch means
and element maxima), <case>/snapshot65.5ns.png
(solid pressure, von Mises and temperature rise (Fig. 9) on the r-z
section, mirrored about the axis, at the write time nearest 65.5 ns) and <case>/postProcessing/
blastSummary.dat (probe peaks, arrival time, coupling statistics).
Several cases (pulse or mesh study): the Fig. 10 curves on one figure
<prefix>fig10.png, the interface maxima against time of every case on
<prefix>interfaceMaxima.png and a summary table on stdout.
"""
import sys
import os
import numpy as np

try:
    from neuronFsi import script
except ImportError:
    sys.exit("plotBlast.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import blastPlots as bp
from neuronFsi import resultDigest

# -acceptHandMade: the logs measured without (or against) their runs'
# digests (made or edited by hand, or written before them); by default
# such a log is refused naming it and its first changed line
args = [a for a in sys.argv[1:] if a != "-acceptHandMade"]
resultDigest.measuring("-acceptHandMade", len(args) < len(sys.argv) - 1)
# -partial: a run going on, or stopped between its writes, measured so far
# (its rows after its last write time; refused without it)
given = len(args)
args = [a for a in args if a != "-partial"]
resultDigest.measuringPartial(len(args) < given)
prefix, labels, cases, until = None, [], [], np.inf
i = 0
while i < len(args):
    if args[i] == "-o":
        prefix = args[i + 1]; i += 2
    elif args[i] == "-until":
        until = float(args[i + 1]); i += 2
    elif args[i] == "-label":
        labels.append(args[i + 1]); i += 2
    else:
        cases.append(args[i]); i += 1
if not cases:
    sys.exit(__doc__)
labels += [os.path.basename(os.path.abspath(c)) for c in cases[len(labels):]]


def summary(case):
    return bp.summary(case, until)



try:
    if len(cases) == 1:
        case = cases[0]
        # every input read before the first file is written (adv54 n09:
        # fig10.png replaced, then "log.cellBlastFoam: No such file")
        s = summary(case)
        bp.fig10(cases, labels, f"{case}/fig10.png")
        im = bp.interfaceMaxima(case, f"{case}/interfaceMaxima.png", until)
        tk = bp.snapshot(case, f"{case}/snapshot65.5ns.png")
        lines = ["# probe 0 (cytoplasm-nucleus interface, 75 % nucleus height)",
                 f"# peaks over t <= {until*1e9:g} ns; arrival: first p above half "
                 "the pulse's amplitude;"
                 " coupling and times: whole run", bp.header, bp.row(labels[0], s)]
        for n, (pm, vmm, pa, vma) in im.items():
            if n.endswith(" patch"):
                lines.append(f"# interface {n[:-6]}: largest mean over the "
                             f"patch length (reported), von Mises {pm:.3f} "
                             f"Pa, shear {vmm:.3f} Pa (t <= {until*1e9:g} "
                             f"ns); whole run {pa:.3f} Pa, {vma:.3f} Pa")
                continue
            lines.append(f"# interface {n}: max pressure {pm/1e6:.3f} MPa, "
                         f"max von Mises {vmm:.3f} Pa (t <= {until*1e9:g} ns); "
                         f"whole run {pa/1e6:.3f} MPa, {vma:.3f} Pa")
        lines.append(f"# snapshot at {tk*1e9:.3f} ns")
        with script.writing(f"{case}/postProcessing/blastSummary.dat") as f:
            f.write("\n".join(lines) + "\n")
        print("\n".join(lines))
    else:
        rows = [bp.row(lab, summary(case)) for case, lab in zip(cases, labels)]
        bp.fig10(cases, labels, f"{prefix or ''}fig10.png")
        bp.interfaceMaximaCases(cases, labels, f"{prefix or ''}interfaceMaxima.png")
        print(f"# probe peaks over t <= {until*1e9:g} ns")
        print(bp.header)
        print("\n".join(rows))
except bp.BlastPlotError as err:
    sys.exit(f"plotBlast.py: error: {err}")
