#!/bin/bash
# d29 (class 3, cellMesh and sweepCase on an indentation case while cellIndentationFoam runs in it): each refused naming the running process; the run ends normally and its mesh file is the one it started with.
. "$(dirname "$0")/../lib.sh"
ind; sed -i "s/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/" constant/indenterProperties; md5sum constant/cell.msh > ../m; cellIndentationFoam > ../l1 2>&1 & p=$!; waitFor 30 test -f .runLock; sleep 1
tryt 60 "cellMesh beside the run" cellMesh; tryt 100 "sweepCase beside the run" sweepCase -case . -entry constant/indenterProperties/radius -values "20e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"
echo "   cell.msh: $(md5sum -c ../m 2>&1 | awk "{print \$2}")"; kill $p; wait $p; echo "   run rc=$?"; ls $W
