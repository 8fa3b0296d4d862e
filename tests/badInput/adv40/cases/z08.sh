#!/bin/bash
# z08: restarts whose end time is not after the latest time: blast run to 2 ns, then startFrom latestTime with endTime 1e-09 (shortened) and with endTime 2e-09 (equal); sod finished, endTime halved: refused saying nothing is to be computed (start after endTime), nothing changed? or exit 0 silently?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; sums > ../before
blastEnd 1e-9 1e-9; try "blast endTime 1e-9 < latest 2e-9" cellBlastFoam; echo "   changed: $(changed ../before)"
blastEnd 2e-9 1e-9; try "blast endTime 2e-9 = latest" cellBlastFoam; echo "   changed: $(changed ../before)"
sodDone; sums > ../before2; t=$(ls -d [0-9]* | sort -g | tail -1); h=$(/usr/bin/python3 -c "print(repr($t/2))")
sed -i "s/^endTime .*/endTime $h;/; s/^writeInterval .*/writeInterval $h;/" system/controlDict; try "sod endTime $h < latest $t" rhoRiemannFoam; echo "   changed: $(changed ../before2)"
