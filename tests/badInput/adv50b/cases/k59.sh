#!/bin/bash
# k59 (class 2/3, the main job's indentation stage killed and run again, as the main job runs it: `./Allclean > /dev/null && ./Allrun` in tutorials/indentation/averageCell): a copy of the case; its Allrun SIGKILLed (every process in the folder) 3 s after cellIndentationFoam's log appears; then `./Allclean && ./Allrun` again, SIGKILLed the same way. Expected: the second Allclean and Allrun run (the stale lock of the killed run taken over or removed, no step skipped), the solver started again from the protocol's start; what the killed run left is said or cleaned; nothing hangs.
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/indentation/averageCell" $W/ia; cd $W/ia; P=$PWD
./Allrun > $W/a1.log 2>&1 & a=$!; waitFor 250 test -f log.cellIndentationFoam; sleep 3; killAll $P; kill -KILL $a 2>/dev/null; wait $a 2>/dev/null
echo "   killed 1: $(ls -a | grep -i 'log\.\|lock\|postProcessing' | tr '\n' ' ') | force rows $(nLines postProcessing/indentation/force.dat)"
./Allclean > $W/c2.log 2>&1; echo "   Allclean rc=$? $(grep -a -i -m1 'lock\|refus\|error' $W/c2.log | cut -c1-200) | left: $(ls -a | grep -i 'log\.\|lock\|postProcessing' | tr '\n' ' ')"
./Allrun > $W/a2.log 2>&1 & a=$!; waitFor 250 test -f log.cellIndentationFoam; sleep 3; echo "   second Allrun: $(grep -a -i -m2 'lock\|refus\|error\|skip' $W/a2.log | cut -c1-160 | tr '\n' '|') $(grep -a '^Running' $W/a2.log | tr '\n' ' ' | cut -c1-200)"
echo "   solver log: $(grep -a -m1 -i 'step 1\|Protocol\|row' log.cellIndentationFoam 2>/dev/null | cut -c1-120)"; killAll $P; kill -KILL $a 2>/dev/null; wait $a 2>/dev/null; killAll $P; echo "   killed 2: $(ls -a | grep -i 'log\.\|lock' | tr '\n' ' ')"
