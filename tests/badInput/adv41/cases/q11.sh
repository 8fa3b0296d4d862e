#!/bin/bash
# q11: rhoRiemannFoam -overwrite from a RESTARTED waterPulseWall (probes/0 and probes/<restart time>): the user's note in the later segment; then in probes/0 as a hidden file
. "$(dirname "$0")/../lib.sh"
wpDone 2e-8; sed -i 's/^endTime .*/endTime 4e-8;/; s/^startFrom .*/startFrom latestTime;/' system/controlDict; timeout -s KILL 200 rhoRiemannFoam > log.2 2>&1; echo "segments: $(ls postProcessing/probes | tr '\n' ' ')"
s=$(ls postProcessing/probes | sort -g | tail -1); echo "q11 later note" > postProcessing/probes/$s/notes.txt; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; sums > ../before
tryf "-overwrite (note in probes/$s)" rhoRiemannFoam -overwrite; kept "q11 later note"; nochange ../before
rm -f postProcessing/probes/$s/notes.txt; echo "q11 hidden" > postProcessing/probes/0/.hidden; tryf "-overwrite (.hidden in probes/0)" rhoRiemannFoam -overwrite; kept "q11 hidden"
