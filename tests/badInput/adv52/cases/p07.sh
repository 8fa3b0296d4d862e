#!/bin/bash
# CASETIMEOUT=900
# p07 (new, class 5: damage of constant/inflowWave, planeWave -inflow's output that the planeWaveInflow boundary reads):
# the inflow preview (ibd: -Z 40e-6 -inflow 20e-6, run to 2e-9), its results removed (a fresh start), constant/inflowWave
# with (a) the second column of its rows before 1e-9 s multiplied by 1.5 (a parse-valid edit or bit flip), (b) a row
# cut in the middle (its last token lost), (c) two rows swapped (time out of order); each run to 1e-9. Expected: the
# damage named (a digest of the file planeWave wrote, or the order/shape checked); (a) run to its end with 1e-09/p far
# from the undamaged run's and no word = SILENT.
. "$(dirname "$0")/../lib.sh"
ibd; cp 1e-09/p $W/p.ref; fresh; sed -i "/^endTime\|^writeInterval/d" system/controlDict.allrun; printf 'endTime 1e-9;\nwriteInterval 1e-9;\n' >> system/controlDict.allrun
cp -a . $W/i0; back() { cd $W; rm -rf iblast; cp -a i0 iblast; cd iblast; }
head -c 600 constant/inflowWave | grep -a -v '^ *$' | head -12 | sed 's/^/   inflowWave: /'
cmpP() { [ -f 1e-09/p ] && /usr/bin/python3 -c "
import sys, numpy as np; from neuronFsi import foamField as f
a = np.asarray(f.internalField('1e-09/p')); b = np.asarray(f.internalField(sys.argv[1]))
print('   1e-09/p against the undamaged run: largest difference %.3g Pa of %.3g Pa' % (np.abs(a-b).max(), np.abs(b).max()))" $W/p.ref; }
one() { tryt 400 "$1" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 4 | cut -c1-300)"; cmpP; }
ed() { /usr/bin/python3 - constant/inflowWave "$1" <<'P'
import re, sys
p, how = sys.argv[1:3]; L = open(p).read().split('\n')
num = re.compile(r'^\s*\(?\s*[-+0-9.eE]+(\s+[-+0-9.eE]+)+\s*\)?\s*$')
rows = [i for i, l in enumerate(L) if num.match(l)]
print('   %d numeric rows; first: %s' % (len(rows), L[rows[0]].strip() if rows else '-'))
if how == 'scale':
    n = 0
    for i in rows:
        t = L[i].replace('(', ' ').replace(')', ' ').split()
        if float(t[0]) < 1e-9:
            t[1] = repr(float(t[1]) * 1.5); L[i] = ('(' if '(' in L[i] else '') + ' '.join(t) + (')' if ')' in L[i] else ''); n += 1
    print('   scaled column 2 of %d rows' % n)
elif how == 'cut':
    i = rows[len(rows) // 2]; L[i] = ' '.join(L[i].split()[:-1]); print('   row %d cut: %s' % (i, L[i]))
elif how == 'swap':
    i, j = rows[len(rows) // 3], rows[len(rows) // 3 + 1]; L[i], L[j] = L[j], L[i]; print('   rows %d and %d swapped' % (i, j))
open(p, 'w').write('\n'.join(L))
P
}
ed scale; one "(a) inflowWave's column 2 x1.5 before 1e-9"; back
ed cut; one "(b) inflowWave: a row cut"; back
ed swap; one "(c) inflowWave: two rows swapped"
