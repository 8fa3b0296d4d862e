#!/bin/bash
# w115: blast with a planeWaveInflow top (-Z 40 um, -inflow 20 um; constant/inflowWave written by the Allrun): the pulse in 0/p changed to 30 MPa, then endTime past the wave file's end, then the thermo changed, each run by hand: refused naming the mismatch?
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 40e-6 -inflow 20e-6 -endTime 2e-9 -writeInterval 1e-9 -noPlots -noVTK -noRun > log.prep 2>&1; echo "prep rc=$?"; cp 0/p ../p0
sed -i 's/50000000/30000000/g' 0/p; try "pulse 30 MPa in 0/p" cellBlastFoam; rm -rf solid postProcessing [1-9]*; cp ../p0 0/p
printf 'endTime 6e-9;\nwriteInterval 1e-9;\n' > system/controlDict.allrun; try "endTime 6 ns (wave to 3 ns)" cellBlastFoam; grep -a -A1 "FATAL" $W/try.log | tail -1 | cut -c1-250; rm -rf solid postProcessing [1-9]*; printf 'endTime 2e-9;\nwriteInterval 1e-9;\n' > system/controlDict.allrun
sed -i 's/^\( *C0 *\)1450;/\11500;/' constant/thermophysicalProperties; try "C0 1500" cellBlastFoam
