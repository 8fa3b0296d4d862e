#!/bin/bash
# CASETIMEOUT=900
# p04 (new, class 1/2: an indentation restarted from an OLDER checkpoint than its results): the smoke indentation with
# 10x finer depth steps (ik: killed 1 s after its first checkpoint); its restart.h5 kept aside; the restart run 4 s and
# SIGKILLed (later checkpoints, more force.dat rows and solid.h5 steps); then the kept (older) restart.h5 put back and the
# run restarted to its end. Expected: refused (restart.h5 older than the results: named) or the results cut back to the
# checkpoint and continued so that force.dat equals an uninterrupted run's (no duplicated or missing rows); force.dat
# with rows of two time lines or solid.h5 steps out of order = SILENT.
. "$(dirname "$0")/../lib.sh"
ik; I=postProcessing/indentation; cp $I/restart.h5 $W/old.h5; echo "   after ik: force rows $(grep -vc '^#' $I/force.dat), solid.h5 steps $(h5steps $I/solid.h5)"
cellIndentationFoam > log.r1 2>&1 & p=$!; sleep 4; kill -KILL $p; wait $p 2>/dev/null; rm -f .runLock
echo "   after the second kill: force rows $(grep -vc '^#' $I/force.dat), solid.h5 steps $(h5steps $I/solid.h5), restart.h5 $(cmp -s $I/restart.h5 $W/old.h5 && echo same || echo newer)"
cp $W/old.h5 $I/restart.h5; tryt 600 "(a) restart from the older restart.h5 to the end" cellIndentationFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 4 | cut -c1-300)"
echo "   force.dat rows $(grep -vc '^#' $I/force.dat); duplicated times: $(grep -v '^#' $I/force.dat | awk '{print $1}' | sort | uniq -d | wc -l); non-increasing: $(grep -v '^#' $I/force.dat | awk 'NR>1 && $1<=p {n++} {p=$1} END {print n+0}')"
cd $W; mv ind ikrun; ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; tryt 600 "(ref) the same case uninterrupted" cellIndentationFoam
/usr/bin/python3 - $W/ikrun/$I/force.dat $W/ind/$I/force.dat <<'P'
import sys, numpy as np
a = np.loadtxt(sys.argv[1], comments='#', ndmin=2, usecols=(0, 1, 2, 3, 4)); b = np.loadtxt(sys.argv[2], comments='#', ndmin=2, usecols=(0, 1, 2, 3, 4))
n = min(len(a), len(b)); d = np.abs(a[:n] - b[:n]).max() if n else float('nan')
print('   restarted vs uninterrupted force.dat: rows %d vs %d, largest difference over the common rows %.3g' % (len(a), len(b), d))
P
