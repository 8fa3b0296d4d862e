#!/bin/bash
# v48: duplicates: constant/fsiProperties interface fluidPatch given twice (interface, then top)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^\( *fluidPatch *interface;\)/\1 fluidPatch top;/' constant/fsiProperties; grep -n fluidPatch constant/fsiProperties | cut -c1-80; cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 "FATAL" log.run | head -5 | cut -c1-300; echo "rc=$rc"
