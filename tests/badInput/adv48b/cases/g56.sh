#!/bin/bash
# g56 (class 4, an option given twice to the Python tools) planeWave -Z 20e-6 -Z 40e-6, sweepCase -maxRuns 5 -maxRuns 5000, paperFigures -output a -output b -noRun, calibrateCell -nProcs 1 -nProcs 4, pulseStudy -dict x -dict y: each refused naming the option given twice (as the C++ tools' checkRepeatedOptions), never the last value taken silently.
. "$(dirname "$0")/../lib.sh"
bd; tryt 60 "planeWave -Z twice" planeWave -case . -Z 20e-6 -Z 40e-6; tail -1 $W/try.log | cut -c1-150
tryt 60 "sweepCase -maxRuns twice" sweepCase -case . -entry constant/fsiProperties/coupling/maxIter -values "30 31" -output "x=postProcessing/fsi/0/coupling.dat:max:2" -maxRuns 5 -maxRuns 5000 -run true; killIn $W; tail -1 $W/try.log | cut -c1-150
cp -r $ROOT/tutorials/paper $W/paper; cd $W/paper; tryt 60 "paperFigures -output twice" paperFigures -noRun -output $W/pa -output $W/pb; killIn $W; ls -d $W/pa $W/pb 2>&1 | cut -c1-100 | tr '\n' ' '; echo
cal; tryt 60 "calibrateCell -nProcs twice" calibrateCell -case . -nProcs 1 -nProcs 4 -dict system/nope; tail -1 $W/try.log | cut -c1-150
study; cp system/pulseStudyDict system/d2; tryt 60 "pulseStudy -dict twice" pulseStudy -dict system/nope -dict system/d2; killIn $W; tail -1 $W/try.log | cut -c1-150
