#!/bin/bash
# i26 (class 3/HANG, a lock that is a FIFO, for every tool): .runLock a FIFO (no writer; then with a writer holding it open)
# in bd (rs) for cellBlastFoam, cellMesh, solidToFoam, planeWave -check, sweepCase, the preview's
# Allrun and Allclean; in the calibration tutorial for calibrateCell; in the pulseStudy folder for pulseStudy: each refused
# within seconds naming the lock and "FIFO" (60 s KILL timeout: rc 137 = HANG), nothing changed, the FIFO left.
. "$(dirname "$0")/../lib.sh"
bd; rs; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; mkfifo .runLock; sums > ../s0
for c in cellBlastFoam cellMesh solidToFoam "planeWave -check" "sweepCase -entry constant/fsiProperties/coupling/maxIter -values 30 -output x=postProcessing/fsi/0/coupling.dat:-1:1 -name x" "./Allrun $PREV -noRun" ./Allclean; do
  tryt 60 "$c" $c; echo "      $(grep -a -m1 -i 'lock\|fifo' $W/try.log | cut -c1-220)"; done; echo "   changed: $(changed ../s0) | lock: $(stat -c %F .runLock)"
sleep 200 > .runLock & S=$!; sleep 0.2; tryt 60 "with a writer: cellBlastFoam" cellBlastFoam; tryt 60 "with a writer: planeWave -check" planeWave -check; kill $S 2>/dev/null
cal; mkfifo .runLock; tryt 60 "calibrateCell" calibrateCell -nProcs 1; echo "   lock: $(stat -c %F .runLock)"
study; mkdir -p postProcessing/pulseStudy; mkfifo postProcessing/pulseStudy/.runLock; mkfifo .runLock; tryt 60 "pulseStudy" pulseStudy; echo "   left: $(ls -d postProcessing/pulseStudy/* 2>/dev/null | tr '\n' ' ')"
