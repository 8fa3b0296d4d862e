#!/bin/bash
# k60 (class 2/3, the main job's preview stage killed and run again, as the main job runs it: `./Allclean > /dev/null && ./Allrun` in tutorials/blast/axisymmetricPreview, default options): a copy of the case; its Allrun SIGKILLed (every process in the folder) 2 s after its planeWave -inflow step's log (or the solver's log) appears; then `./Allclean && ./Allrun` again, SIGKILLed once it reaches the same step. Expected: the second Allclean and Allrun run from the start (no stale lock refusal, no step skipped because the killed run left its log, .allrunOptions not refused as another run's), nothing hangs.
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/pa; cd $W/pa; P=$PWD; st() { ls log.planeWave* log.cellBlastFoam 2>/dev/null | head -1; }; stq() { [ -n "$(st)" ]; }
./Allrun > $W/a1.log 2>&1 & a=$!; waitFor 400 stq; sleep 2; echo "   run 1 reached $(st)"; killAll $P; kill -KILL $a 2>/dev/null; wait $a 2>/dev/null; killAll $P
echo "   killed 1: $(ls -a | grep -i 'log\.\|lock\|allrunOptions' | tr '\n' ' ')"
./Allclean > $W/c2.log 2>&1; echo "   Allclean rc=$? $(grep -a -i -m1 'lock\|refus\|error' $W/c2.log | cut -c1-200) | left: $(ls -a | grep -i 'log\.\|lock\|processor\|allrunOptions' | tr '\n' ' ')"
(./Allrun > $W/a2.log 2>&1; echo "rc=$?" >> $W/a2.log) & a=$!; waitFor 400 stq; sleep 2
echo "   second: reached $(st) | Allrun $(grep -a -i -m2 'lock\|refus\|error\|skip\|already' $W/a2.log | cut -c1-200 | tr '\n' '|') $(tail -1 $W/a2.log | cut -c1-120)"
killAll $P; kill -KILL $a 2>/dev/null; wait $a 2>/dev/null; killAll $P
