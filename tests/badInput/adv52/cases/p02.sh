#!/bin/bash
# CASETIMEOUT=900
# p02 (new, class 3: two runs at once through tools not tried): (a) planeWave -case C twice at once on the finished
# preview (bd): both write postProcessing/planeWave and run a 1D column; (b) tutorials/indentation/gapStudy.sh averageCell
# NAME twice at once with the same WORK and NAME; (c) solidToFoam twice at once on bd's solid/solid.h5. Expected: the
# second refused naming the first (in use), the first's outputs whole; both running into one folder (a mixed or cut
# reference.dat, a removed case under a running solver) = DATALOSS.
. "$(dirname "$0")/../lib.sh"
bd; C=$PWD
planeWave -case $C > $W/pw1.log 2>&1 & P1=$!; sleep 3
tryt 300 "(a) a second planeWave -case C while the first runs" planeWave -case $C; echo "   second said: $(grep -a -m2 -i 'error\|refus\|in use' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"
wait $P1; echo "   first rc $? | $(grep -a -m2 -i 'error\|refus\|in use' $W/pw1.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"
R=postProcessing/planeWave/0/reference.dat; echo "   reference.dat rows: $(grep -vc '^#' $R 2>/dev/null) | files: $(ls postProcessing/planeWave/0 2>/dev/null | tr '\n' ' ')"
cd $W; export WORK=$W/gw; mkdir -p $WORK
bash $ROOT/tutorials/indentation/gapStudy.sh averageCell same > $W/g1.log 2>&1 & P1=$!; sleep 6; echo "   first gapStudy at 6 s: $(ls $WORK 2>/dev/null | tr '\n' ' ') $(inDir $WORK | cut -c1-150)"
tryt 300 "(b) a second gapStudy.sh averageCell same (same WORK) while the first runs" bash $ROOT/tutorials/indentation/gapStudy.sh averageCell same
echo "   second: $(grep -a -v '^ *$' $W/try.log | tail -2 | tr '\n' '|' | cut -c1-300)"; wait $P1; echo "   first rc $? | $(grep -a -v '^ *$' $W/g1.log | tail -2 | tr '\n' '|' | cut -c1-300)"
cd $W; rm -rf blast; bd; rm -rf constant/solid
solidToFoam solid/solid.h5 > $W/s1.log 2>&1 & P1=$!; sleep 0.5
tryt 120 "(c) a second solidToFoam while the first runs" solidToFoam solid/solid.h5; wait $P1; echo "   first rc $? | second said: $(grep -a -m1 -i 'in use\|error' $W/try.log | cut -c1-200)"
