#!/bin/bash
# b31 (class 1+4, solidToFoam -region of odd names, then the documented restart): a blast run to 2 ns; solidToFoam solid/solid.h5 -region each of "sölid", "a b", "", ".", "cellX": each written or refused naming the option; then (z19's kind with another region name) the restart to 3 ns after "-region cellX": continues (the region's mesh is no input of the solver), or refused as a changed input?
. "$(dirname "$0")/../lib.sh"
blastDone
for r in "sölid" "a b" "" "." ; do tryf "-region '$r'" solidToFoam solid/solid.h5 -region "$r"; done; echo "   constant/: $(ls constant | tr '\n' ' ')"
rm -rf "constant/sölid" "2e-09/sölid" "1e-09/sölid"; tryf "-region cellX" solidToFoam solid/solid.h5 -region cellX; echo "   constant/cellX: $(ls constant/cellX 2>/dev/null | tr '\n' ' ')"
latest; blastEnd 3e-9 1e-9; tryf "restart to 3e-9 after -region cellX" cellBlastFoam; echo "   times: $(ls -d [1-9]* | tr '\n' ' ')"
