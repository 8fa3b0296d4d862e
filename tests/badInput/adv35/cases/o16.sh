#!/bin/bash
# o16: blast: after o05 (a failed -overwrite emptied the solid outputs), restart latestTime
. "$(dirname "$0")/../lib.sh"
blastDone; setd constant/fsiProperties coupling/scheme robinn; cellBlastFoam -overwrite > log.ow 2>&1; echo "overwrite rc=$?"; setd constant/fsiProperties coupling/scheme robin
setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9
cellBlastFoam > log.run 2>&1; rc=$?; grep -A4 "FATAL" log.run | head -6; echo "rc=$rc"; h5ls solid/solid.h5/steps
