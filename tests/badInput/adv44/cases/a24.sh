#!/bin/bash
# a24 (class 4, solidToFoam -region names that are not a region): a finished blast; solidToFoam solid/solid.h5 -region R for R = 0 (the start time's name), 1e-09 (a written time), constant, system, polyMesh, processor0, "", ".", "a b", "-x": refused before writing naming the option, or a region folder written inside a time directory / over the case's own folders (and a later restart confused)?
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../s
for r in 0 1e-09 constant system polyMesh processor0 "" . "a b" -x; do tryf "-region '$r'" solidToFoam solid/solid.h5 -region "$r"; c=$(changed ../s); echo "   changed: ${c:0:300}"; done
latest; blastEnd 3e-9 1e-9; tryf "then a restart to 3 ns" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
