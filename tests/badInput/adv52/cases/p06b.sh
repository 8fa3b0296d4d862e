#!/bin/bash
# CASETIMEOUT=900
# p06b (p06 with its premise met: at 2 ns the pulse has not reached the preview's probes): bd continued to 12e-9 (the
# 10 um water probe sees the incident pulse at about 6.7 ns), planeWave -case on it (control measures), then
# (a) postProcessing/fluidProbes/<start>/p: every value of the probe column within 1 ns after its peak x1.5 (a
# parse-valid edit, as a bit flip in a digit would be, over a few rows): planeWave -check; (b) tutorials/blast/
# plotBlast.py and incidentWindow.py on it; (c) postProcessing/planeWave/0/reference.dat's peak rows x1.5: incidentWindow.py.
# Each: the damage named (the logs carry digests in the commit markers: the restart checks them), or at least the
# measure not printed from changed rows without a word; a peak 1.5x the control's printed rc 0 = SILENT.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 12e-9 1e-9; rm -f .runLock; tryt 600 "(0) bd continued to 12e-9" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log)"; cp log.first log.cellBlastFoam 2>/dev/null
C=$PWD; tryt 600 "(0) planeWave -case (control)" planeWave -case $C; grep -a "fluidProbes\|^# probe " $W/try.log | head -4 | cut -c1-250 | sed 's/^/   /'
tryt 200 "(0) incidentWindow.py (control)" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py $C; grep -a -v '^ *$' $W/try.log | tail -2 | cut -c1-200 | sed 's/^/   /'
cp -a . $W/c0; ls postProcessing/fluidProbes | sed 's/^/   fluidProbes folders: /'
/usr/bin/python3 - postProcessing/fluidProbes <<'P'
import glob, os, sys
for p in sorted(glob.glob(os.path.join(sys.argv[1], '*', 'p'))):
    L = open(p).read().split('\n'); rows = [i for i, l in enumerate(L) if l.strip() and not l.startswith('#')]
    if not rows: continue
    v = lambda i: float(L[i].split()[1]); k = max(rows, key=v); t0 = float(L[k].split()[0]); n = 0
    for i in rows:
        t = L[i].split()
        if t0 <= float(t[0]) <= t0 + 1e-9: t[1] = repr(float(t[1]) * 1.5); L[i] = ' '.join(t); n += 1
    open(p, 'w').write('\n'.join(L)); print('   %s: peak %.4g Pa at %.4g s; %d rows within 1 ns after it x1.5' % (p, v(k) / 1.5 if n else v(k), t0, n))
P
tryt 600 "(a) planeWave -check after the probe's rows x1.5" planeWave -case $C -check; grep -a "fluidProbes\|damag\|digest\|edited\|error" $W/try.log | head -4 | cut -c1-250 | sed 's/^/   /'
tryt 200 "(b1) incidentWindow.py" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py $C; grep -a -v '^ *$' $W/try.log | tail -2 | cut -c1-200 | sed 's/^/   /'
tryt 200 "(b2) plotBlast.py" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py $C; grep -a -i 'damag\|digest\|error\|peak' $W/try.log | head -2 | cut -c1-200 | sed 's/^/   /'
cd $W; rm -rf blast; cp -a c0 blast; cd blast; R=postProcessing/planeWave/0/reference.dat
/usr/bin/python3 - $R <<'P'
import sys
p = sys.argv[1]; L = open(p).read().split('\n'); rows = [i for i, l in enumerate(L) if l.strip() and not l.startswith('#')]
n = 0
for i in rows:
    t = L[i].split()
    for j in (1, 2):
        if abs(float(t[j])) > 1e6: t[j] = repr(float(t[j]) * 1.5); n += 1
    L[i] = ' '.join(t)
open(p, 'w').write('\n'.join(L)); print('   %s: pressure columns x1.5 where above 1 MPa: %d values' % (p, n))
P
tryt 200 "(c) incidentWindow.py after reference.dat's rows x1.5" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py $C; grep -a -v '^ *$' $W/try.log | tail -2 | cut -c1-200 | sed 's/^/   /'
