#!/bin/bash
# k55 (class 4/2, write controls at their edges): fresh previews: (a) writeInterval 5e-9 > endTime 2e-9 (adjustableRunTime: no write time before the end; the guarantee: the last time always written); (b) writeControl timeStep with writeInterval 1.0 (a count written as a real) and 1e1; (c) writeInterval equal to endTime (2e-9). Expected: (a) and (c) end with 2e-09 written and committed; (b) refused naming the digits as written, or run writing every step count; nothing silently without a restart point.
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 2e-9 5e-9; tryt 200 "(a) writeInterval 5e-9, endTime 2e-9" cellBlastFoam; after; marks 2e-09
for v in 1.0 1e1; do cd $W; rm -rf blast; blast; printf 'endTime 2e-11;\nwriteControl timeStep;\nwriteInterval %s;\n' $v > system/controlDict.allrun; tryt 200 "(b) writeControl timeStep, writeInterval $v" cellBlastFoam; after; done
cd $W; rm -rf blast; blast; blastEnd 2e-9 2e-9; tryt 200 "(c) writeInterval = endTime" cellBlastFoam; after
