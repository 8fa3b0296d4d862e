#!/bin/bash
# k37 (class 1, the same band written otherwise): bd's restart to 3e-9 (R: the reference), and bd with motionDistance 5e-6 written as 5.0e-6, then as 0.000005, then as 5e-6 in fsiProperties.allrun (the same value, another file). Expected: the same value continues (no false refusal) and the result equals R bitwise; a refusal must name the entry and say what differs (a value equal as read is no change).
. "$(dirname "$0")/../lib.sh"
bd; rs; tryt 200 "reference restart" cellBlastFoam; away R
for v in 5.0e-6 0.000005; do bd; rs; sete constant/fsiProperties motionDistance $v > /dev/null; tryt 200 "motionDistance written $v" cellBlastFoam; cont; after; cmpRef $W/R; cd $W; rm -rf blast; done
bd; rs; echo 'interface { motionDistance 5e-6; }' > constant/fsiProperties.allrun; tryt 200 "the same value in fsiProperties.allrun" cellBlastFoam; cont; after; cmpRef $W/R
