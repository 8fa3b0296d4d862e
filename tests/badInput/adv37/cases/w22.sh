#!/bin/bash
# w22: blast run to 2 ns, fsiProperties coupling scheme robin -> aitken and load pressure kept, restart: refused naming the entry (class 1: coupling settings)?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; sed -i 's/scheme          robin;/scheme          aitken;/' constant/fsiProperties; grep -n "scheme " constant/fsiProperties
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
