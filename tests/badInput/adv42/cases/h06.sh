#!/bin/bash
# h06 (phase C, the new rule must not refuse the run's own files): (a) a fresh blast SIGKILLed before its first commit, no user file: -overwrite runs and equals a clean run? (b) the same with the killed run's solidProbes.dat cut to its first 10 bytes (a header cut by the kill) and coupling.dat empty: taken as the run's, or refused (a false refusal the user must clear by hand)? (c) a killed restart's segment (fsi/1e-09 with coupling.dat cut to 5 bytes), -overwrite from 0
. "$(dirname "$0")/../lib.sh"
blastDone; cd ..; mv blast ref; blast; blastEnd 8e-9 4e-9; cellBlastFoam > log.k 2>&1 & p=$!; waitFor 60 test -f postProcessing/solidProbes/0/solidProbes.dat; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; blastEnd 2e-9 1e-9; cd ..; mv blast k0
part() { rm -rf c; cp -r k0 c; cd c; }
part; tryf "(a) -overwrite over the killed fresh run" cellBlastFoam -overwrite; echo "   $(sameSeries ../ref | awk '{print $1, $2}' | tr '\n' ' ')"; cd ..
part; head -c 10 postProcessing/solidProbes/0/solidProbes.dat > x && mv x postProcessing/solidProbes/0/solidProbes.dat; : > postProcessing/fsi/0/coupling.dat; tryf "(b) cut and empty logs of the killed run" cellBlastFoam -overwrite; echo "   $(sameSeries ../ref | awk '{print $1, $2}' | tr '\n' ' ')"; cd ..
cd $W; blast; blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; latest; blastEnd 8e-9 4e-9; cellBlastFoam > log.2 2>&1 & p=$!; waitFor 60 test -s postProcessing/fsi/1e-09/coupling.dat; sleep 0.2; kill -KILL $p; wait $p 2>/dev/null
head -c 5 postProcessing/fsi/1e-09/coupling.dat > x && mv x postProcessing/fsi/1e-09/coupling.dat; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; blastEnd 2e-9 1e-9
tryf "(c) killed restart segment with a cut log, -overwrite from 0" cellBlastFoam -overwrite; echo "   $(sameSeries $W/ref | awk '{print $1, $2}' | tr '\n' ' ')"
