#!/bin/bash
# CASETIMEOUT=900
# p13 (new, class 1: restarts from times another tool wrote - decomposePar, reconstructPar - after an input changed):
# (a) bd (serial, 2e-09 committed), then one coefficient of the water law in constant/thermophysicalProperties x1.01,
# decomposePar -latestTime (processor*/2e-09 written by decomposePar: no commit marker of ours), mpirun -np 2
# cellBlastFoam -parallel restart to 3e-9; (b) pbd (2 ranks), reconstructPar -latestTime (2e-09 in the case), the same
# input change, serial restart to 3e-9. Expected: both refused naming the changed file and entry (the input record read
# from the decomposed/reconstructed time's uniform/inputDigests), or refused as times without our commit; a restart that
# continues with the changed law = SILENT.
. "$(dirname "$0")/../lib.sh"
chg() { /usr/bin/python3 - constant/thermophysicalProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); m = re.search(r'\b(C0|Gamma0|gamma)\s+([-+0-9.eE]+)\s*;', t)
t = t[:m.start(2)] + repr(float(m.group(2)) * 1.01) + t[m.end(2):]; open(p, 'w').write(t); print('   thermophysicalProperties: %s %s -> %s' % (m.group(1), m.group(2), repr(float(m.group(2)) * 1.01)))
P
}
res() { echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 4 | cut -c1-350)"; }
bd; rs; rm -f .runLock; splitY 4e-6; chg; tryt 200 "(a0) decomposePar -latestTime" decomposePar -latestTime; echo "   processor0/2e-09: $(ls -a processor0/2e-09 2>/dev/null | tr '\n' ' ') | uniform: $(ls processor0/2e-09/uniform 2>/dev/null | tr '\n' ' ')"
tryt 300 "(a) 2-rank restart to 3e-9 from decomposePar's 2e-09 with the changed law" mpirun -np 2 cellBlastFoam -parallel; res
cd $W; pbd; rs; rm -f .runLock; tryt 200 "(b0) reconstructPar -latestTime" reconstructPar -latestTime; echo "   2e-09: $(ls -a 2e-09 2>/dev/null | tr '\n' ' ') | uniform: $(ls 2e-09/uniform 2>/dev/null | tr '\n' ' ')"
chg; tryt 300 "(b) serial restart to 3e-9 from reconstructPar's 2e-09 with the changed law" cellBlastFoam; res
