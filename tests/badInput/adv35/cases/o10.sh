#!/bin/bash
# o10: solidToFoam twice over the same solid.h5
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam postProcessing/indentation/solid.h5 > l1 2>&1; echo "rc1=$?"; solidToFoam postProcessing/indentation/solid.h5 2>&1 | tail -3; echo "rc2=${PIPESTATUS[0]}"; ls
