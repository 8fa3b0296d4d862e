#!/bin/bash
# h02 (phase C, a log renamed by the user): (a) a finished blast, the user renamed fsi/0/coupling.dat to coupling.dat.bak (a recorded folder) and copied solidProbes/0/solidProbes.dat to solidProbes.dat.orig; (b) a fresh run SIGKILLed before its first commit, the user renamed solidProbes/0/solidProbes.dat to old.dat (an unrecorded folder); -overwrite: the renamed files (kept by the user) refused by name, or removed?
. "$(dirname "$0")/../lib.sh"
blastDone; cp postProcessing/solidProbes/0/solidProbes.dat postProcessing/solidProbes/0/solidProbes.dat.orig; mv postProcessing/fsi/0/coupling.dat postProcessing/fsi/0/coupling.dat.bak; md5sum postProcessing/fsi/0/coupling.dat.bak postProcessing/solidProbes/0/solidProbes.dat.orig > ../m.a
tryf "(a) renamed/copied logs in recorded folders, -overwrite" cellBlastFoam -overwrite; md5sum -c ../m.a 2>&1 | tr "\n" " "; echo
cd $W; rm -rf blast; blast; blastEnd 8e-9 4e-9; cellBlastFoam > log.k 2>&1 & p=$!; waitFor 60 test -f postProcessing/solidProbes/0/solidProbes.dat; sleep 0.5; kill -KILL $p; wait $p 2>/dev/null; blastEnd 2e-9 1e-9
mv postProcessing/solidProbes/0/solidProbes.dat postProcessing/solidProbes/0/old.dat; md5sum postProcessing/solidProbes/0/old.dat > ../m.b
tryf "(b) the killed run's log renamed old.dat, -overwrite" cellBlastFoam -overwrite; md5sum -c ../m.b 2>&1 | tr '\n' ' '; echo
