#!/bin/bash
# q06: -overwrite with HIDDEN files of the user's in the function objects' folders: postProcessing/fsi/0/.notes, postProcessing/fluidProbes/0/.~lock.p# (an editor's lock), postProcessing/solidInterfaces/0/.hidden/x: kept or refused naming them?
. "$(dirname "$0")/../lib.sh"
blastDone; echo "q06 hidden notes" > postProcessing/fsi/0/.notes; echo "q06 editor lock" > "postProcessing/fluidProbes/0/.~lock.p#"; mkdir -p postProcessing/solidInterfaces/0/.hidden; echo "q06 hidden dir" > postProcessing/solidInterfaces/0/.hidden/x
sums > ../before; tryf "-overwrite" cellBlastFoam -overwrite; kept "q06 hidden notes" "q06 editor lock" "q06 hidden dir"
