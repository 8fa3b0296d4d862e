#!/bin/bash
# CASETIMEOUT=600
# m05b (m05's (g) mended: the sod tube's endTime is riemannProblemDict's $endTime; and the parallel preview): (g) the sod
# tube (rhoRiemannFoam, ascii, writePrecision 12 as its tutorial) with controlDict's endTime and writeInterval set to
# 0.0035 s (half), then restarted to 0.007 s: the k58 warning expected; the restarted 0.007/rho against an uninterrupted
# run's (ascii 12 both: compared as written); (h) the 2-rank preview (pbd: binary 17) run 0 -> 1e-9 with writePrecision
# 8, restarted to 2e-9 on 2 ranks: the warning (once, by the master?) and the fields against pbd's 2e-09 (binary 17).
. "$(dirname "$0")/../lib.sh"
sod; cp -a . ../s0; sed -i 's/^endTime .*/endTime 0.0035;/; s/^writeInterval .*/writeInterval 0.0035;/' system/controlDict
timeout -s KILL 300 rhoRiemannFoam > log.first 2>&1; echo "(g) sod to 0.0035 s: rc $? | times: $(ls -d [0-9]* | tr '\n' ' ')"
sed -i 's/^endTime .*/endTime 0.007;/; s/^writeInterval .*/writeInterval 0.007;/; s/^startFrom .*/startFrom latestTime;/' system/controlDict
tryt 300 "(g) sod restart to 0.007 s" rhoRiemannFoam; echo "   warning lines: $(grep -a -c -i 'writePrecision' $W/try.log) | $(grep -a -m1 -i 'writePrecision' $W/try.log | cut -c1-250)"
cd $W/s0; timeout -s KILL 300 rhoRiemannFoam > log.first 2>&1; echo "   uninterrupted sod: rc $? | times: $(ls -d [0-9]* | tr '\n' ' ')"
/usr/bin/python3 - $W/sod/0.007/rho $W/s0/0.007/rho <<'P'
import re, sys
def r(p):
    b = open(p).read(); k = b.index('internalField'); m = re.compile(r'nonuniform\s+List<scalar>\s*(\d+)\s*\(').search(b, k); e = b.index('\n)', m.end())
    return [float(x) for x in b[m.end():e].split()]
a, c = r(sys.argv[1]), r(sys.argv[2]); d = max(abs(x - y) for x, y in zip(a, c)); print('   0.007/rho restarted vs uninterrupted: max |diff| %.3e kg/m^3 (of %.3e)' % (d, max(c)))
P
cd $W; pbd; rm -rf processor*/[1-9]* postProcessing solid; P=$PWD; cd $W; pblast; rm -f .runLock
sed -i 's/^writePrecision .*/writePrecision 8;/' system/controlDict; blastEnd 1e-9 1e-9; timeout -s KILL 300 mpirun -np 2 cellBlastFoam -parallel > log.first 2>&1; echo "(h) 2 ranks to 1e-9 with writePrecision 8: rc $?"
latest; blastEnd 2e-9 1e-9; tryt 300 "(h) 2-rank restart to 2e-9" mpirun -np 2 cellBlastFoam -parallel; echo "   warning lines: $(grep -a -c -i 'writePrecision' $W/try.log) | $(grep -a -m1 -i 'writePrecision' $W/try.log | cut -c1-250) | End: $(grep -a -c '^End' $W/try.log)"
cd $W/pblast; for r in 0 1; do echo "   processor$r/2e-09/p vs pbd's: $(cmp -s processor$r/2e-09/p $ADV/pbdBase/processor$r/2e-09/p && echo 'same bytes' || echo DIFFERENT)"; done
