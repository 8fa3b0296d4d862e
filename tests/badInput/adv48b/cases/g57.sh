#!/bin/bash
# g57 (class 3, planeWave -inflow -overwrite while the run reads the wave) ibd restarted to 3e-9 in the background; during it planeWave -inflow 20e-6 -Z 60e-6 -overwrite (another wave): refused naming the run (the case in use), constant/inflowWave unchanged; the run finishes 3e-09 on the wave it started with.
. "$(dirname "$0")/../lib.sh"
ibd; latest; iEnd 1e-8; cp constant/inflowWave ../iw0; cellBlastFoam > ../run.log 2>&1 & p=$!; waitFor 60 test -s .runLock; sleep 2
tryt 200 "planeWave -inflow -overwrite during the run" planeWave -inflow 20e-6 -Z 60e-6 -overwrite; cmp -s constant/inflowWave ../iw0 && echo "   inflowWave unchanged" || echo "   inflowWave REWRITTEN during the run"; wait $p; echo "   run rc=$? $(grep -a -m1 'FATAL' ../run.log)"; after
