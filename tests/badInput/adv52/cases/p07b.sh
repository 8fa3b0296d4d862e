#!/bin/bash
# CASETIMEOUT=900
# p07b (p07 (a) with its premise met: ibd's inflowWave covers 0-2 ns, before the wave reaches the inflow plane, all its
# rows zero): the inflow preview prepared by its Allrun with -endTime 16e-9 (iblast 16e-9: -Z 40e-6 -inflow 20e-6; the
# wave crosses the plane at about 13 ns), run to 16e-9 undamaged (reference); then a copy whose constant/inflowWave has
# the second number of every non-zero row multiplied by 1.5 (a parse-valid edit of planeWave -inflow's output), run to
# 16e-9. Expected: the damage named (a digest of what planeWave wrote), rc != 0; a run to its end with 16e-09/p different
# from the reference and no word = SILENT.
. "$(dirname "$0")/../lib.sh"
iblast 16e-9; sed -i '/^writeInterval/d' system/controlDict.allrun; echo 'writeInterval 16e-9;' >> system/controlDict.allrun; cp -a . $W/i0
tryt 600 "(ref) the undamaged inflow preview to 16e-9" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | times: $(ls -d [0-9]* | tr '\n' ' ')"; cp 1.6e-08/p $W/p.ref 2>/dev/null || cp $(ls -d [1-9]* | sort -g | tail -1)/p $W/p.ref
cd $W; rm -rf c; cp -a i0 c; cd c; /usr/bin/python3 - constant/inflowWave <<'P'
import re, sys
p = sys.argv[1]; L = open(p).read().split('\n'); num = re.compile(r'^\s*\(\s*[-+0-9.eE]+(\s+[-+0-9.eE]+)+\s*\)\s*$'); n = 0
for i, l in enumerate(L):
    if num.match(l):
        t = l.replace('(', ' ').replace(')', ' ').split()
        if float(t[1]) != 0.0:
            t[1] = repr(float(t[1]) * 1.5); L[i] = '(' + ' '.join(t) + ')'; n += 1
open(p, 'w').write('\n'.join(L)); print('   inflowWave: %d non-zero rows, second number x1.5' % n)
P
tryt 600 "(a) inflowWave's non-zero rows x1.5, run to 16e-9" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 4 | cut -c1-300)"
T=$(ls -d [1-9]* 2>/dev/null | sort -g | tail -1); [ -n "$T" ] && /usr/bin/python3 -c "
import sys, numpy as np; from neuronFsi import foamField as f
a = np.asarray(f.internalField(sys.argv[1])); b = np.asarray(f.internalField(sys.argv[2]))
print('   %s/p against the undamaged run: largest difference %.4g Pa of %.4g Pa' % (sys.argv[3], np.abs(a-b).max(), np.abs(b).max()))" $T/p $W/p.ref $T
