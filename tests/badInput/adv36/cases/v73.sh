#!/bin/bash
# v73: duplicates: constant/thermophysicalProperties mieGruneisenCoeffs C0 given twice
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^\( *C0 *[0-9.e+-]*;\)/\1 C0 1000;/' constant/thermophysicalProperties; grep -n " C0" constant/thermophysicalProperties | cut -c1-80; cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"
