#!/bin/bash
# g13 (class 1, the inflow's wave) ibd (planeWaveInflow top, run to 2e-09): constant/inflowWave rewritten by planeWave -inflow for another column (-Z 40e-6 -dz 25e-9: the same column in 25 nm cells instead of 50 nm (corrected after P1b: -Z 60e-6 is refused by planeWave as not the case's column): a valid wave of its own digest, -overwrite), restart latestTime to 3e-9: refused naming constant/inflowWave (the incident wave changed under the run), nothing written.
. "$(dirname "$0")/../lib.sh"
ibd; latest; iEnd 3e-9; cp constant/inflowWave ../iw0; tryt 200 "planeWave -inflow 20e-6 -Z 40e-6 -dz 25e-9 -overwrite" planeWave -inflow 20e-6 -Z 40e-6 -dz 25e-9 -overwrite; cmp -s constant/inflowWave ../iw0 && echo "   inflowWave unchanged" || echo "   inflowWave rewritten"; sums > ../s0
tryt 240 "restart with the other column's wave" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
