#!/bin/bash
# q09: -overwrite on 2 ranks with the user's file in postProcessing/solidProbes/0/ and in postProcessing/fluidProbes/0/: refused (both ranks agree, no half-moved case) or kept?
. "$(dirname "$0")/../lib.sh"
pblastDone; echo "q09 solid note" > postProcessing/solidProbes/0/notes.txt; echo "q09 fluid note" > postProcessing/fluidProbes/0/notes.txt 2>/dev/null || echo "(no postProcessing/fluidProbes/0 on 2 ranks: $(ls postProcessing))"
sums > ../before; run 120 mpirun -np 2 cellBlastFoam -parallel -overwrite > log.ow 2>&1 | tail -1; fatal log.ow 4; kept "q09 solid note" "q09 fluid note"; nochange ../before
