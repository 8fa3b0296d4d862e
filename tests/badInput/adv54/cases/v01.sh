#!/bin/bash
# CASETIMEOUT=600
# v01 (fix19j row "outputs: our text results edited or made by hand", varied: the parallel run, other logs, other tools):
# (a) pbd (the 2-rank preview, finished at 2e-9): postProcessing/fluidProbes/0/p's 20th row's pressure x1.5 (the logs of
# a parallel run are written once, by rank 0; its markers are processor0/<t>/.writeCommitted): planeWave -check;
# (b) bd: postProcessing/fsi/0/coupling.dat's 5th data row changed (a residual x10): plotBlast.py (it reads the coupling
# statistics) and bench/blast/analysis/late.py; (c) bd: postProcessing/solidProbes/0/solidProbes.dat one row changed:
# planeWave (solid probes' measures); (d) the same edit in (a) with -acceptHandMade (measured, as the option says).
# Expected: (a)-(c) refused naming the file and the row's line; an edited row measured without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
rowx() { /usr/bin/python3 - "$@" <<'P'
import sys
p, n, col, f = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
L = open(p).read().split("\n"); data = [i for i, l in enumerate(L) if l.strip() and not l.lstrip().startswith("#")]
k = data[n - 1]; w = L[k].split(); w[col] = repr(float(w[col]) * f); L[k] = "  ".join(w); open(p, "w").write("\n".join(L))
print("   %s line %d -> %s" % (p, k + 1, L[k][:120]))
P
}
pbd; ls postProcessing/ | tr '\n' ' '; echo; ls processor0 | tr '\n' ' '; echo; f=postProcessing/fluidProbes/0/p; rowx $f 20 1 1.5; ok_ $f
tryt 300 "(a) 2 ranks: planeWave -check" planeWave -case . -check; echo "   said: $(say 2 | cut -c1-300)"
tryt 300 "(d) 2 ranks: planeWave -check -acceptHandMade" planeWave -case . -check -acceptHandMade; echo "   said: $(say 1 | cut -c1-200)"
cd $W; bd; cp log.first log.cellBlastFoam; f=postProcessing/fsi/0/coupling.dat; head -n 3 $f | cut -c1-200; rowx $f 5 2 10; ok_ $f
tryt 300 "(b) plotBlast.py on coupling.dat edited" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .; echo "   said: $(say 2 | cut -c1-300)"
tryt 300 "(b) analysis/late.py" /usr/bin/python3 $ROOT/bench/blast/analysis/late.py .; echo "   said: $(say 2 | cut -c1-300) | last: $(tail -n 1 $W/try.log | cut -c1-150)"
cd $W; rm -rf blast; bd; f=postProcessing/solidProbes/0/solidProbes.dat; head -n 2 $f | cut -c1-200; rowx $f 30 2 1.5; ok_ $f
tryt 300 "(c) planeWave on solidProbes.dat edited" planeWave -case .; echo "   said: $(say 2 | cut -c1-300)"
