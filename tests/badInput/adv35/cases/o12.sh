#!/bin/bash
# o12: solidToFoam after the user edited a field in the converted region (re-conversion overwrites?)
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam postProcessing/indentation/solid.h5 > l1 2>&1; t=$(ls -d [0-9]* | tail -1); ls $t; ls $t/solid | head; echo "user" > $t/solid/myNote; solidToFoam postProcessing/indentation/solid.h5 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"; ls $t/solid/myNote
