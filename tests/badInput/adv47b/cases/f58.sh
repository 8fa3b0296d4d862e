#!/bin/bash
# (corrected after its first run: two kills gave the same rows; b is now ik, the base killed with 30 rows and its checkpoint at step 30)
# f58 (class 1, indentation, a checkpoint later than the case's own force.dat - f08 with its premise made sure): two smoke indentations with 10x finer steps SIGKILLed 0.2 s and 3 s after their first checkpoint; the restart.h5 of the one with more force.dat rows put into the one with fewer, restart: refused (force.dat shorter than the checkpoint, or another run's checkpoint), or continued with force.dat having every row (times increasing, no gap); never rows missing between the case's last row and the checkpoint without a word.
. "$(dirname "$0")/../lib.sh"
indKilled 0.2; mv $W/ind $W/a; ik; mv $W/ind $W/b; na=$(grep -vc '^#' $W/a/postProcessing/indentation/force.dat); nb=$(grep -vc '^#' $W/b/postProcessing/indentation/force.dat); echo "   rows a $na b $nb"
if [ $na -lt $nb ]; then lo=a hi=b; else lo=b hi=a; fi; [ $na = $nb ] && echo "   n/r: same rows"
cd $W/$lo; cp $W/$hi/postProcessing/indentation/restart.h5 postProcessing/indentation/; sums > ../s0
tryt 240 "case $lo (fewer rows) with $hi's restart.h5" cellIndentationFoam; cont; echo "   changed: $(changed ../s0)"; after; forceOk postProcessing/indentation/force.dat
/usr/bin/python3 - postProcessing/indentation/force.dat <<'P'
import sys
t = [float(l.split()[0]) for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
d = [b - a for a, b in zip(t, t[1:])]; print("   force.dat time steps: min %.3g max %.3g s (a gap shows as a step far above the others)" % (min(d), max(d)))
P
