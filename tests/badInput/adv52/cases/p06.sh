#!/bin/bash
# CASETIMEOUT=900
# p06 (new, class 5: parse-valid damage of the text outputs the analysis reads; g61 zeroed bytes, here one number changed
# as a bit flip or an edit would): the finished preview with planeWave's reference (pwd0): (a) postProcessing/fluidProbes
# /0/p: the row of the probe's peak with its value x1.5; planeWave -check on it (measures from the probe's series);
# (b) the same damage, then the restart to 3e-9 (does the restart check its function objects' logs against the commit
# markers?); (c) postProcessing/solidProbes/0/solidProbes.dat: the peak row's pressure x1.5, then tutorials/blast/
# plotBlast.py and tests/blast/checkLongRun.py; (d) postProcessing/planeWave/0/reference.dat: its peak row x1.5, then
# incidentWindow.py. Each: the damage named (checksum of the file against its commit) or at least never a measure
# printed from the changed row without a word; the peak x1.5 in the printed measure with rc 0 = SILENT.
. "$(dirname "$0")/../lib.sh"
pwd0; cp log.first log.cellBlastFoam; C=$PWD; cp -a . $W/pw0
back() { cd $W; rm -rf pw; cp -a pw0 pw; cd pw; }
bump() { /usr/bin/python3 - "$1" "$2" <<'P'
import sys
p, col = sys.argv[1], int(sys.argv[2]); L = open(p).read().split('\n')
rows = [i for i, l in enumerate(L) if l.strip() and not l.startswith('#')]
def v(i):
    try: return abs(float(L[i].split()[col]))
    except Exception: return -1
k = max(rows, key=v); t = L[k].split(); old = t[col]; t[col] = repr(float(old) * 1.5); L[k] = ' '.join(t)
open(p, 'w').write('\n'.join(L)); print('   %s row %d column %d: %s -> %s' % (p, k, col, old, t[col]))
P
}
tryt 300 "(0) planeWave -check (control)" planeWave -case $C -check; grep -a -i "peak\|error\|%" $W/try.log | head -6 | cut -c1-160 | sed 's/^/   /'
bump postProcessing/fluidProbes/0/p 1; tryt 300 "(a) planeWave -check after fluidProbes/0/p's peak x1.5" planeWave -case $C -check; grep -a -i "peak\|error\|%\|damag\|checksum\|digest" $W/try.log | head -6 | cut -c1-160 | sed 's/^/   /'
latest; blastEnd 3e-9 1e-9; tryt 300 "(b) the restart to 3e-9 with that probe log" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-250)"; back
bump postProcessing/solidProbes/0/solidProbes.dat 1; tryt 200 "(c1) checkLongRun.py" /usr/bin/python3 $ROOT/tests/blast/checkLongRun.py $C 2e-9; grep -a -i "peak\|damag\|checksum" $W/try.log | head -2 | cut -c1-200 | sed 's/^/   /'
tryt 200 "(c2) plotBlast.py" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py $C; grep -a -v '^ *$' $W/try.log | tail -2 | cut -c1-200 | sed 's/^/   /'; back
tryt 200 "(d0) incidentWindow.py (control)" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py $C; grep -a -v '^ *$' $W/try.log | tail -3 | cut -c1-200 | sed 's/^/   /'
bump postProcessing/planeWave/0/reference.dat 1; tryt 200 "(d) incidentWindow.py after reference.dat's peak x1.5" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py $C; grep -a -v '^ *$' $W/try.log | tail -3 | cut -c1-200 | sed 's/^/   /'
tryt 300 "(d2) planeWave -check after reference.dat's peak x1.5" planeWave -case $C -check; grep -a -i "peak\|error\|%\|damag" $W/try.log | head -4 | cut -c1-160 | sed 's/^/   /'
