#!/bin/bash
# q08: -overwrite from a RESTARTED run (segments postProcessing/*/0 and */1e-09): the user's file in the START time's segment of one function object (solidInterfaces/0/notes.txt) and in a LATER segment of another (fluidProbes/1e-09/plot.png); refused naming both (or kept); results untouched when refused?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; latest; blastEnd 2e-9 1e-9; cellBlastFoam > log.2 2>&1; echo "segments: $(ls postProcessing/*/ | tr '\n' ' ')"
echo "q08 start segment note" > postProcessing/solidInterfaces/0/notes.txt; echo "q08 later segment plot" > postProcessing/fluidProbes/1e-09/plot.png
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; sums > ../before
tryf "-overwrite" cellBlastFoam -overwrite; kept "q08 start segment note" "q08 later segment plot"; nochange ../before
rm -f postProcessing/solidInterfaces/0/notes.txt; sums > ../before2; tryf "-overwrite (start note removed)" cellBlastFoam -overwrite; kept "q08 later segment plot"
