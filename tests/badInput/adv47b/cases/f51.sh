#!/bin/bash
# f51 (class 4, the FSI coupling tolerance at its bound): a new start of the preview with constant/fsiProperties coupling tolerance 0.1 (the bound: accepted, runs; stopped after 30 s) and 0.10000000000000002 (refused naming tolerance and its range).
. "$(dirname "$0")/../lib.sh"
blast; cp constant/fsiProperties ../f0
for v in 0.1 0.10000000000000002; do cp ../f0 constant/fsiProperties; sed -i "s/^    tolerance       1e-4;/    tolerance       $v;/" constant/fsiProperties; n=$(grep -c "tolerance       $v;" constant/fsiProperties); tryt 30 "coupling tolerance $v (edit $n)" cellBlastFoam; rm -rf [1-9]* postProcessing solid .runLock; done
