#!/usr/bin/python3
"""Pressure and von Mises fields of an indentation case at a peak.

usage: plotFields.py [-acceptHandMade] <case> [label]     (label: a line of peaks.dat,
                                         default C1,i, the first peak)

Reads <case>/postProcessing/indentation/{peaks.dat,solid.h5} and writes
<case>/fields_<label>.png: the r-z section (deformed) coloured by the
element pressure and von Mises stress [Pa], with the region boundaries,
like the paper's Figs. 7 and 8 (it shows C2,ii at 26.88 s), and prints
the extremes per region.
"""
import os
import sys

try:
    from neuronFsi import script
except ImportError:
    sys.exit("plotFields.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import indentationPlots as ip
from neuronFsi import resultDigest

# -acceptHandMade: force.dat and peaks.dat measured without (or against)
# their digests (a file made or edited by hand; refused by default)
args = [a for a in sys.argv[1:] if a != "-acceptHandMade"]
resultDigest.measuring("-acceptHandMade", len(args) < len(sys.argv) - 1)
if len(args) not in (1, 2):
    sys.exit("plotFields.py: error: usage: plotFields.py [-acceptHandMade] "
             "<case> [label]")
case = args[0]
label = args[1] if len(args) > 1 else "C1,i"
try:
    rows, peaks = ip.read(case)
    if label not in peaks:
        sys.exit("plotFields: no peak '%s' in %s (have: %s)"
                 % (label, os.path.join(case, "postProcessing", "indentation",
                                        "peaks.dat"), " ".join(peaks)))
    f = ip.fields(case, peaks[label][0])
except ip.IndentationPlotError as err:
    sys.exit("plotFields: %s" % err)
png = os.path.join(case, "fields_%s.png" % label.replace(",", "_"))
ip.fieldsFigure(f, png, "at %s (t = %.2f s)" % (label, f.t))
for n, pmin, pmax, vmax in ip.regionExtremes(f):
    print("%-10s pressure %9.2f .. %9.2f Pa, von Mises max %9.2f Pa"
          % (n, pmin, pmax, vmax))
print("Written", png)
