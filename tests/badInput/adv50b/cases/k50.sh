#!/bin/bash
# k50 (class 3, planeWave -inflow -overwrite while the run that reads constant/inflowWave goes): the inflow preview (iblast: -Z 40e-6 -inflow 20e-6, 2 ns) set to 30e-9 and started in the background; while it runs, planeWave -inflow 20e-6 -Z 60e-6 -overwrite (another wave) in the case. Expected: refused naming the running run (one run per case), constant/inflowWave unchanged; if replaced, the restart after the run refuses naming it.
. "$(dirname "$0")/../lib.sh"
iblast 30e-9; mv $W/c $W/i; cd $W/i; md5sum constant/inflowWave | cut -c1-8 > $W/w0; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 120 test -f .runLock; sleep 2
tryt 300 "planeWave -inflow -overwrite (other wave) while the run goes" planeWave -case . -inflow 20e-6 -Z 60e-6 -overwrite; echo "   inflowWave: $(cat $W/w0) -> $(md5sum constant/inflowWave | cut -c1-8); run alive: $(kill -0 $p 2>/dev/null && echo yes || echo no)"
sleep 2; kill -KILL $p; wait $p 2>/dev/null; rm -f .runLock; latest; iEnd 31e-9; tryt 200 "restart after it" cellBlastFoam; cont; after
