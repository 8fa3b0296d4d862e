#!/bin/bash
# w94: planeWave -inflow 10e-6 started while cellBlastFoam runs in the case (it would write constant/inflowWave under the running solver): refused (lock)?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 8e-9 1e-9; cellBlastFoam > log.a 2>&1 & p=$!; sleep 1; try inflow planeWave -case . -inflow 10e-6; ls constant | tr '\n' ' '; wait $p; echo "solver rc=$?"
