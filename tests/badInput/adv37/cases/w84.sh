#!/bin/bash
# w84: two utilities at once in one case: cellMesh and solidToFoam started together on a finished blast case: one refused (lock), the other done, nothing broken?
. "$(dirname "$0")/../lib.sh"
blastDone; md5sum constant/cell.msh > ../m; cellMesh > log.cm 2>&1 & p=$!; solidToFoam solid/solid.h5 > log.s2f 2>&1; echo "solidToFoam rc=$?"; wait $p; echo "cellMesh rc=$?"; fatal log.cm 2; fatal log.s2f 2; md5sum -c ../m
