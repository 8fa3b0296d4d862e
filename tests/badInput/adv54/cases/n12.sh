#!/bin/bash
# CASETIMEOUT=600
# n12 (new, class 1/5: another run's time folder copied into a case - a user "merging" two runs): bd and bd2 (the pulse
# doubled) each restarted to 3e-9; bd2's 3e-09 copied over bd's 3e-09 (cp -a, the whole folder with its marker). Then in
# bd: planeWave -check, incidentWindow.py, and a restart to 4e-9. Expected: the restart refused ("belongs to another
# run"), the measures refused or naming 3e-09 as another run's; bd's own probe log refused as "edited" (it is not) =
# UNCLEAR; measured with bd2's time folder without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
bd2; rs; rm -f .runLock; tryt 300 "bd2 to 3e-9" cellBlastFoam; B2=$PWD; cd $W; bd; rs; rm -f .runLock; tryt 300 "bd to 3e-9" cellBlastFoam
rm -rf 3e-09; cp -a $B2/3e-09 .; tryt 300 "planeWave -check in bd with bd2's 3e-09" planeWave -case . -check; echo "   said: $(say 3 | cut -c1-300)"
iw .; echo "   incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -n 2 | tr '\n' '|' | cut -c1-300)"
blastEnd 4e-9 1e-9; rm -f .runLock; tryt 300 "restart to 4e-9 from bd2's 3e-09" cellBlastFoam; echo "   said: $(say 3 | cut -c1-300)"
