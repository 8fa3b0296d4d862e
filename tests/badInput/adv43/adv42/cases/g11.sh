#!/bin/bash
# g11 (class 2, purgeWrite and a user's file in a time directory): purgeWrite 2, run to 2 ns (1e-09 and 2e-09 kept); the user's notes.txt in 1e-09/ and a sub-folder 2e-09/myPost/ with a file; restart to 4 ns (purgeWrite removes 1e-09 and 2e-09): the user's files removed with them without a word, refused, or kept?
. "$(dirname "$0")/../lib.sh"
blast; echo "purgeWrite 2;" >> system/controlDict.allrun; run 120 cellBlastFoam > log.first 2>&1; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
echo "g11 note in 1e-09" > 1e-09/notes.txt; mkdir 2e-09/myPost; echo "g11 my post" > 2e-09/myPost/a.csv
latest; blastEnd 4e-9 1e-9; echo "purgeWrite 2;" >> system/controlDict.allrun; tryf "restart to 4 ns, purgeWrite 2" cellBlastFoam; grep -a -i -m2 'purg\|user\|not written' $W/try.log | cut -c1-200; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; kept "g11 note in 1e-09" "g11 my post"
