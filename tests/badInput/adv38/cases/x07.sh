#!/bin/bash
# x07: blast preview Allrun (small options, to 6 ns) running in the real path; planeWave and sweepCase started through a SYMBOLIC LINK to the case: refused as the same case (real path), the Allrun's results whole?
. "$(dirname "$0")/../lib.sh"
prev; ln -s $W/c $W/link; ./Allrun $PREV -endTime 6e-9 > ../log.a 2>&1 & p=$!
waitFor 120 test -f log.cellBlastFoam; sleep 1; echo "lock: $(lockOf)"
cd $W/link; try "planeWave via link" planeWave -Z 20e-6 -dz 50e-9; try "sweepCase via link" sweepCase -entry constant/fsiProperties/coupling/maxIter -values '20 25' -run cellBlastFoam -output 'postProcessing/fsi/0/coupling.dat:1' -name mi; cd $W/c
wait $p; echo "Allrun exit $?"; tail -1 ../log.a; ls -d [1-9]* | tr '\n' ' '; echo; ls $W
