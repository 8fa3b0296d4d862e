#!/bin/bash
# w20: blast run to 2 ns, constant/solidProperties shearViscosity 0.2 -> 0 (the solid's numerical viscosity), restart: refused naming the entry?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; sed -i 's/^shearViscosity  0.2;/shearViscosity  0;/' constant/solidProperties; grep -n "^shearViscosity " constant/solidProperties
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
