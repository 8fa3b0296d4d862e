#!/bin/bash
# g35 (class 2, g10's mechanism): finished to 2 ns; the user's notes.md ("# My analysis") and a plain notes.txt put in postProcessing/fsi/2e-09/ BEFORE the restart from 2e-09 to 3e-09 (the folder the restart then writes its segment into); what does 3e-09/.writeCommitted record for that folder? then -overwrite from 0: which of the two is refused or removed?
. "$(dirname "$0")/../lib.sh"
blastDone; mkdir -p postProcessing/fsi/2e-09; printf '# My analysis g35\n' > postProcessing/fsi/2e-09/notes.md; printf 'g35 plain notes\n' > postProcessing/fsi/2e-09/notes.txt
latest; blastEnd 3e-9 1e-9; tryf "restart 2 -> 3 ns" cellBlastFoam; echo "   3e-09/.writeCommitted lines naming fsi/2e-09: $(grep -a 'fsi/2e-09' 3e-09/.writeCommitted | cut -c1-120 | tr '\n' '|')"
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; blastEnd 2e-9 1e-9; tryf "-overwrite from 0" cellBlastFoam -overwrite; kept "My analysis g35" "g35 plain notes"
