#!/bin/bash
# q14: -overwrite where the user's file has the NAME of a log the run writes but sits in another function object's folder (postProcessing/fsi/0/solidProbes.dat, a copy the user made) and an empty file of the user's (postProcessing/solidProbes/0/TODO); kept or refused naming them?
. "$(dirname "$0")/../lib.sh"
blastDone; (echo "# q14 user copy"; cat postProcessing/solidProbes/0/solidProbes.dat) > postProcessing/fsi/0/solidProbes.dat; : > postProcessing/solidProbes/0/TODO
sums > ../before; tryf "-overwrite" cellBlastFoam -overwrite; kept "q14 user copy"; [ -e postProcessing/solidProbes/0/TODO ] && echo "   TODO kept" || echo "   TODO: $(find . -name TODO | tr '\n' ' ')${NONE:-(not found)}"
