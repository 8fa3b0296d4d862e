#!/bin/bash
# x66: planeWave on a finished 20-um-column blast run with the WRONG column height (-Z 40e-6, another -dz) or an -endTime shorter/longer than the run: refused (the run's column is in its mesh), or a comparison against another 1D problem without a word?
. "$(dirname "$0")/../lib.sh"
blastDone; try "-Z 40e-6" planeWave -Z 40e-6 -dz 50e-9; grep -a "^fluidProbes\|arrival" postProcessing/planeWave/*.dat 2>/dev/null | head -2 | cut -c1-150; rm -rf postProcessing/planeWave
try "-Z 10e-6" planeWave -Z 10e-6 -dz 50e-9; rm -rf postProcessing/planeWave; try "-endTime 5e-9" planeWave -Z 20e-6 -dz 50e-9 -endTime 5e-9
