#!/bin/bash
# k28: ind: restart.h5 replaced by the one of a run with another radius (same mesh), restart
. "$(dirname "$0")/../lib.sh"
indDone; mkdir ../other; cp -r system constant ../other/; (cd ../other && setd constant/indenterProperties radius 20e-6 && cellIndentationFoam > log 2>&1); cp ../other/postProcessing/indentation/restart.h5 postProcessing/indentation/; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
