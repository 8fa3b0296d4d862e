#!/bin/bash
# CASETIMEOUT=600
# n05 (new, class 5/1: a killed indentation's results changed, then a legitimate restart): ik (the smoke indentation with
# fine steps SIGKILLed after its first checkpoint): (a) force.dat.fnv1a64 deleted (a user tidying "junk" files), restart
# (startFrom latestTime) to the end, plotIndentation.py; (b) force.dat's 2nd row's force x1.5 (sidecar kept), restart,
# plotIndentation.py; (c) (b) and the sidecar deleted, restart, plotIndentation.py. Expected: the restart refuses the
# changed file (or the reader refuses after it); an edited row measured in the end without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
ik; cp -a . $W/k0; d=postProcessing/indentation; echo "   ik: force rows $(grep -vc '^#' $d/force.dat), sidecar lines $(wc -l < $d/force.dat.fnv1a64)"
x15() { /usr/bin/python3 - $d/force.dat <<'P'
import sys
p = sys.argv[1]; L = open(p).read().split("\n"); k = [i for i, l in enumerate(L) if l and not l.startswith("#")][1]
f = L[k].split(); f[2] = repr(float(f[2]) * 1.5); L[k] = " ".join(f); open(p, "w").write("\n".join(L)); print("   row", k + 1, "->", L[k])
P
}
latest; rm -f .runLock; rm $d/force.dat.fnv1a64; tryt 400 "(a) sidecar deleted: restart" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"; pi; echo "   (a) $(pk)"; ok_ $d/force.dat
cd $W; rm -rf ind; cp -a k0 ind; cd ind; latest; rm -f .runLock; x15; tryt 400 "(b) row 2 x1.5: restart" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"; pi; echo "   (b) $(pk)"
cd $W; rm -rf ind; cp -a k0 ind; cd ind; latest; rm -f .runLock; x15; rm $d/force.dat.fnv1a64; tryt 400 "(c) row 2 x1.5, sidecar deleted: restart" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"; pi; echo "   (c) $(pk)"; ok_ $d/force.dat
