#!/bin/bash
# x46: after w113's refusal the advice followed exactly: rm log.cellBlastFoam.running, startFrom latestTime, cellBlastFoam by hand to its end, then ./Allrun for the post-processing: exit 0, times to 8 ns, the solver not re-run, the fields equal an uninterrupted Allrun's?
. "$(dirname "$0")/../lib.sh"
prev; setsid ./Allrun $PREV -endTime 8e-9 > ../log.a1 2>&1 & p=$!; waitFor 120 test -d 3e-09; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5
run 100 ./Allrun $PREV -endTime 8e-9 > ../log.a2 2>&1; rm -f log.cellBlastFoam.running; latest; run 200 cellBlastFoam > log.hand 2>&1; tail -1 log.hand
run 200 ./Allrun $PREV -endTime 8e-9 > ../log.a3 2>&1; echo "fourth: $(tail -1 ../log.a3 | cut -c1-150)"; grep -a -i "error\|refus" ../log.a3 | head -3 | cut -c1-250; echo "times: $(ls -d [1-9]* | tr '\n' ' ')"
cp -r $ROOT/tutorials/blast/axisymmetricPreview $W/ref; cd $W/ref; ./Allrun $PREV -endTime 8e-9 > ../log.ref 2>&1; cmp 8e-09/p $W/c/8e-09/p && echo "8e-09/p equal to the uninterrupted Allrun"; cmp postProcessing/fsi/0/coupling.dat $W/c/postProcessing/fsi/0/coupling.dat && echo "coupling.dat equal"
