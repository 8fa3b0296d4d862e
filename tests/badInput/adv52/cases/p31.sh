#!/bin/bash
# CASETIMEOUT=300
# p31 (new, class 5: p06b's parse-valid edit in the indentation's text results, read by its analysis): the finished
# smoke indentation idn: (a) postProcessing/indentation/force.dat's force column x1.5 in every row of stage B;
# tutorials/indentation/plotIndentation.py and plotFields.py; (b) peaks.dat's values x1.5: plotIndentation.py. The
# checkpoint restart.h5 records force.dat's digest (p23: the restart refuses an edited force.dat). Expected: the edit
# named by the readers, or at least never F_B printed 1.5x the control's without a word (= SILENT).
. "$(dirname "$0")/../lib.sh"
idn; I=postProcessing/indentation; py() { tryt 120 "$1" /usr/bin/python3 "${@:2}"; grep -a -v '^ *$' $W/try.log | grep -a -i "F_B\|C1\|error\|damag\|digest\|edited" | head -4 | cut -c1-200 | sed 's/^/   /'; }
py "(0) plotIndentation.py (control)" $ROOT/tutorials/indentation/plotIndentation.py .
cp -a . $W/i0; /usr/bin/python3 - $I/force.dat <<'P'
import sys
p = sys.argv[1]; L = open(p).read().split('\n'); n = 0
for i, l in enumerate(L):
    t = l.split()
    if l.strip() and not l.startswith('#') and t[-1] == 'B': t[1] = repr(float(t[1]) * 1.5); L[i] = ' '.join(t); n += 1
open(p, 'w').write('\n'.join(L)); print('   force.dat: %d stage-B rows x1.5' % n)
P
py "(a) plotIndentation.py after force.dat's stage B x1.5" $ROOT/tutorials/indentation/plotIndentation.py .
cd $W; rm -rf ind; cp -a i0 ind; cd ind; cat $I/peaks.dat | head -4 | sed 's/^/   peaks.dat: /'
/usr/bin/python3 - $I/peaks.dat <<'P'
import sys
p = sys.argv[1]; L = open(p).read().split('\n'); n = 0
for i, l in enumerate(L):
    t = l.split()
    if l.strip() and not l.startswith('#'):
        for j in range(1, len(t)):
            try: t[j] = repr(float(t[j]) * 1.5); n += 1
            except ValueError: pass
        L[i] = ' '.join(t)
open(p, 'w').write('\n'.join(L)); print('   peaks.dat: %d numbers x1.5' % n)
P
py "(b) plotIndentation.py after peaks.dat x1.5" $ROOT/tutorials/indentation/plotIndentation.py .
