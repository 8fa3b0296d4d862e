#!/bin/bash
# i19 (class 1/SILENT, the band motion with the structured cell on 2 ranks): sbd's prepared case (structured, motionDistance
# 5e-6, 14 um column) split in two ranks at y = 4 um (the band crosses the ranks' boundary across the cell), run on 2 ranks
# from 0 to 5e-9 (the pulse on the cell from ~4 ns), reconstructed: its logs and solid.h5 against the serial sbd: equal (the
# parallel run gives the serial values) or within round-off (1e-10 relative); then (b) the same with motionDistance 2e-6
# (a band ending inside a rank) against nothing: exit 0.
. "$(dirname "$0")/../lib.sh"
sbd; S=$PWD; cp -a $S $W/p; cd $W/p; fresh; splitY 4e-6; decomposePar -force > log.decompose 2>&1 || tail -3 log.decompose
tryt 600 "2 ranks, structured, motionDistance 5e-6" mpirun -np 2 cellBlastFoam -parallel; closeTo $S; sameSeries $S | sed 's/^/   /'
echo "   solid.h5 vs serial: $(h5same solid/solid.h5 $S/solid/solid.h5)"
cp -a $S $W/p2; cd $W/p2; fresh; echo 'motionDistance 2e-6;' > ../x; sed -i 's/motionDistance[^;]*;/motionDistance 2e-6;/' constant/fsiProperties constant/fsiProperties.allrun 2>/dev/null; grep -h motionDistance constant/fsiProperties* | head -2
splitY 4e-6; decomposePar -force > log.decompose 2>&1; tryt 600 "(b) 2 ranks, motionDistance 2e-6" mpirun -np 2 cellBlastFoam -parallel; echo "   times: $(ls -d processor0/[1-9]* | tr '\n' ' ')"
