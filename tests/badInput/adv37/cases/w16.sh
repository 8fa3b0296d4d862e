#!/bin/bash
# w16: blast run to 2 ns, then system/fvSchemes reconstruct(p) MUSCL -> vanLeer (the face reconstruction), restart to 3 ns: accepted (numerics) or refused? said?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; sed -i 's/reconstruct(p)      MUSCL;/reconstruct(p)      vanLeer;/' system/fvSchemes; grep -n "reconstruct(p)" system/fvSchemes
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 6; tail -1 log.r; grep -a -i "fvSchemes\|changed" log.r | head -3
