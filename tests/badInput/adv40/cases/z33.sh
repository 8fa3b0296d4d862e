#!/bin/bash
# z33: planeWave on a finished blast case, then a user's notes.txt put in postProcessing/planeWave/0/ beside its tables and planeWave run again (its outputs are documented to be replaced): the note kept?
. "$(dirname "$0")/../lib.sh"
blastDone; run 200 planeWave -Z 20e-6 -dz 50e-9 > log.pw1 2>&1 | tail -1; ls postProcessing/planeWave/0 | tr '\n' ' '; echo
echo "my notes" > postProcessing/planeWave/0/notes.txt; run 200 planeWave -Z 20e-6 -dz 50e-9 > log.pw2 2>&1 | tail -1; echo "notes.txt: $(cat postProcessing/planeWave/0/notes.txt 2>/dev/null || echo GONE)"; ls -a postProcessing/planeWave postProcessing/planeWave/0 | tr '\n' ' '; echo
