#!/bin/bash
# CASETIMEOUT=900
# m06 (fix19g's traceback fixes, adv50b k18-k23/k53 (checkLongRun.py, incidentWindow.py), varied): (a) incidentWindow.py on
# the finished preview with planeWave's reference (pwd0): --level nan, inf, -1, 0, 2, 1e400, --foot nan, -1e-9, 1e300,
# --series of a probe that does not exist and of words; (b) its inputs damaged: reference.dat emptied, header only, a row
# cut mid-line, a nan row; the probes' p file cut mid-line and with a nan row; the case a file; (c) checkLongRun.py on the
# finished preview: endTime abc, nan, -1, 1e400, no endTime, a case that does not exist, log.cellBlastFoam missing,
# fsi/coupling.dat emptied or cut mid-line, solidProbes.dat missing, solid.h5 missing or truncated; (d) checkQuarterRun.sh
# on the preview and on nothing. Each: rc != 0 with one line naming what is wrong (or the result), never a traceback.
. "$(dirname "$0")/../lib.sh"
tb() { echo "   traceback: $(grep -a -c '^Traceback' $W/try.log) | last: $(grep -av '^ *$' $W/try.log | tail -2 | tr '\n' ' ' | cut -c1-300)"; }
pwd0; P=$PWD; cp -a $P $W/pw0
for o in "--level nan" "--level inf" "--level -1" "--level 0" "--level 2" "--level 1e400" "--foot nan" "--foot -1e-9" "--foot 1e300" "--series nosuch a b" "--series 1 2 3"; do iw $o $P; tb; done
R=postProcessing/planeWave/0/reference.dat; echo "   reference: $(wc -l < $R) lines, head: $(head -2 $R | tr '\n' '|' | cut -c1-200)"
back() { cd $W; rm -rf pw; cp -a pw0 pw; cd pw; P=$PWD; }
back; : > $R; iw $P; echo "   (b) reference emptied"; tb
back; grep '^#' $R > $R.h; mv $R.h $R; iw $P; echo "   (b) reference header only"; tb
back; n=$(wc -l < $R); head -$((n/2)) $R > $R.h; tail -n +$((n/2+1)) $R | head -1 | cut -c1-7 >> $R.h; mv $R.h $R; iw $P; echo "   (b) reference cut mid-line at half"; tb
back; /usr/bin/python3 - $R <<'Q'
import sys; p = sys.argv[1]; L = open(p).read().split('\n'); i = [k for k, l in enumerate(L) if l and not l.startswith('#')][len(L) // 3]
f = L[i].split(); L[i] = ' '.join([f[0]] + ['nan'] * (len(f) - 1)); open(p, 'w').write('\n'.join(L))
Q
iw $P; echo "   (b) reference with a nan row"; tb
PF=$(ls postProcessing/fluidProbes/0/p 2>/dev/null || find postProcessing -path '*robes*' -name p | head -1); echo "   probes file: $PF"
back; n=$(wc -l < $PF); head -$((n/2)) $PF > $W/pf; tail -n +$((n/2+1)) $PF | head -1 | cut -c1-20 >> $W/pf; cp $W/pf $PF; iw $P; echo "   (b) probes p cut mid-line"; tb
back; sed -i "$(( $(wc -l < $PF) / 2 ))s/ [-0-9.e+]*$/ nan/" $PF; iw $P; echo "   (b) probes p with a nan"; tb
back; iw $P/system/controlDict; echo "   (b) the case a file"; tb
CL="$ROOT/tests/blast/checkLongRun.py"; cl() { local l=$1; shift; tryt 120 "(c) checkLongRun.py $l" /usr/bin/python3 $CL "$@"; tb; }
cd $W; rm -rf pw pw0; bd; B=$PWD; cp -a $B $W/b0; mv log.first log.cellBlastFoam 2>/dev/null
for e in abc nan -1 1e400; do cl "endTime $e" $B $e; done; cl "no endTime" $B; cl "no case" $W/nosuch 2e-9
bb() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; mv log.first log.cellBlastFoam 2>/dev/null; }
bb; rm log.cellBlastFoam; cl "log missing" $B 2e-9
bb; : > postProcessing/fsi/0/coupling.dat 2>/dev/null || : > $(find postProcessing -name coupling.dat | head -1); cl "coupling.dat emptied" $B 2e-9
bb; f=$(find postProcessing -name coupling.dat | head -1); n=$(wc -l < $f); head -c $(( $(stat -c %s $f) - 17 )) $f > $W/c; cp $W/c $f; cl "coupling.dat cut mid-line" $B 2e-9
bb; rm -f $(find postProcessing -name solidProbes.dat); cl "solidProbes.dat missing" $B 2e-9
bb; rm -f solid/solid.h5; cl "solid.h5 missing" $B 2e-9
bb; truncate -s 50% solid/solid.h5; cl "solid.h5 truncated to half" $B 2e-9
bb; cl "the finished 2 ns preview, endTime 2e-9 (control)" $B 2e-9
tryt 200 "(d) checkQuarterRun.sh on the preview" bash "$ROOT/tests/blast/checkQuarterRun.sh" $B; tb
tryt 60 "(d) checkQuarterRun.sh on nothing" bash "$ROOT/tests/blast/checkQuarterRun.sh" $W/nosuch; tb
tryt 60 "(d) checkQuarterRun.sh without an argument" bash "$ROOT/tests/blast/checkQuarterRun.sh"; tb
