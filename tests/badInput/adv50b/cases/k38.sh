#!/bin/bash
# k38 (class 1, band motion changed between a kill and the restart): the prepared preview run to 30e-9 (writes every 1e-9), SIGKILLed after its 3rd commit; motionDistance 5e-6 -> 3e-6 (Allrun's way: constant/fsiProperties.allrun), restart latestTime: refused naming the entry and the file; then the file removed, the restart goes on from the killed run's last time to 6e-9 and ends rc 0.
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 30e-9 1e-9; cellBlastFoam > log.first 2>&1 & p=$!; killAfter 3 $p; rm -f .runLock; ls -d [0-9]* | tr '\n' ' '; echo
latest; blastEnd 6e-9 1e-9; echo 'interface { motionDistance 3e-6; }' > constant/fsiProperties.allrun; sums > ../s0
tryt 300 "restart with motionDistance 3e-6" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
rm -f constant/fsiProperties.allrun; tryt 300 "restart with the band back" cellBlastFoam; cont; after
