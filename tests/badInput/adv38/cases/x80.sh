#!/bin/bash
# x80: the documented by-hand workflow: ./Allrun -noRun (the case prepared), cellBlastFoam run by hand to its end (its output to the terminal, no log.cellBlastFoam), then ./Allrun with the same options for the post-processing: does it post-process the hand run, or re-run the solver over it (refused by the result guard), and is the way out said?
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun $PREV -endTime 2e-9 -noRun > ../log.a1 2>&1; echo "noRun: $(tail -1 ../log.a1 | cut -c1-120)"; cellBlastFoam > ../hand.log 2>&1; echo "hand run rc=$? times $(ls -d [1-9]* | tr '\n' ' ')"
run 200 ./Allrun $PREV -endTime 2e-9 > ../log.a2 2>&1; grep -a -v "^\s*$" ../log.a2 | grep -a -v "From function\|in file" | head -14 | cut -c1-250; echo "times: $(ls -d [1-9]* | tr '\n' ' ')"
