#!/bin/bash
# k61 (class 2/3, the main job's quarter stage killed and run again with its options: `./Allclean > /dev/null && ./Allrun -np 2 -cell 0.7e-6 -lateral 2e-6 -far 10e-6 -inflow 14e-6` in tutorials/blast/quarter3D): its Allrun SIGKILLed (every process in the folder, mpirun and ranks included) 2 s after decomposePar's log or the solver's log appears; then Allclean && Allrun again, SIGKILLed at the same step. Expected: the second run goes from the start (no stale lock or processor folders refused, no step skipped), nothing hangs, no rank left running.
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/quarter3D" $W/qa; cd $W/qa; P=$PWD; O="-np 2 -cell 0.7e-6 -lateral 2e-6 -far 10e-6 -inflow 14e-6"; st() { ls log.decomposePar log.cellBlastFoam 2>/dev/null | tail -1; }; stq() { [ -n "$(st)" ]; }
./Allrun $O > $W/a1.log 2>&1 & a=$!; waitFor 280 stq; sleep 2; echo "   run 1 reached $(st) ($(grep -a '^Running' $W/a1.log | tail -1 | cut -c1-60))"; killAll $P; kill -KILL $a 2>/dev/null; wait $a 2>/dev/null; sleep 1; echo "   left running: $(inDir $P)"
echo "   killed 1: $(ls -a | grep -i 'log\.\|lock\|processor' | tr '\n' ' ')"
./Allclean > $W/c2.log 2>&1; echo "   Allclean rc=$? $(grep -a -i -m1 'lock\|refus\|error' $W/c2.log | cut -c1-200) | left: $(ls -a | grep -i 'log\.\|lock\|processor\|allrunOptions' | tr '\n' ' ')"
(./Allrun $O > $W/a2.log 2>&1; echo "rc=$?" >> $W/a2.log) & a=$!; waitFor 400 stq; sleep 2
echo "   second: reached $(st) | Allrun $(grep -a -i -m2 'lock\|refus\|error\|skip\|already' $W/a2.log | cut -c1-200 | tr '\n' '|') $(tail -1 $W/a2.log | cut -c1-120)"
killAll $P; kill -KILL $a 2>/dev/null; wait $a 2>/dev/null; sleep 1; echo "   left running: $(inDir $P)"
