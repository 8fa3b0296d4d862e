#!/bin/bash
# q10: user's files next to the function objects' time folders (postProcessing/fluidProbes/notes.txt, postProcessing/solidProbes/plot.png: not inside a time) and a folder of the user's named like a time (postProcessing/fsi/5e-09/mine.txt, a time the run never reaches); -overwrite
. "$(dirname "$0")/../lib.sh"
blastDone; echo "q10 beside notes" > postProcessing/fluidProbes/notes.txt; echo "q10 beside plot" > postProcessing/solidProbes/plot.png; mkdir -p postProcessing/fsi/5e-09; echo "q10 time-named folder" > postProcessing/fsi/5e-09/mine.txt
tryf "-overwrite" cellBlastFoam -overwrite; kept "q10 beside notes" "q10 beside plot" "q10 time-named folder"
