#!/bin/bash
# k29: blast: solid/solid.h5 replaced by the one of a run with another shearViscosity, restart
. "$(dirname "$0")/../lib.sh"
blastDone; cp -r . ../other; (cd ../other && rm -rf [1-9]* solid postProcessing && setd constant/solidProperties shearViscosity 0.1 && cellBlastFoam > log.o 2>&1); cp ../other/solid/solid.h5 solid/; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
