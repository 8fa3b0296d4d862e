#!/bin/bash
# w98: blast: a FRESH case run with a bad coupling entry (fsiProperties maxIter 0; also motionNearest 0, onNonConvergence ignore): refused, but are files written before the check? is the corrected run then refused over them? and a finished case's -overwrite with the bad entry: anything lost?
. "$(dirname "$0")/../lib.sh"
blast; cp constant/fsiProperties ../fp; for e in "maxIter 0" "motionNearest 0" "onNonConvergence ignore"; do cp ../fp constant/fsiProperties; k=${e%% *}; sed -i "0,/^\( *\)$k .*/s//\1$e;/" constant/fsiProperties
  run 60 cellBlastFoam > log.bad 2>&1; fatal log.bad 1; echo "  written by the refused run: $(find solid postProcessing -type f 2>/dev/null | tr '\n' ' ')"
  cp ../fp constant/fsiProperties; run 60 cellBlastFoam > log.good 2>&1; fatal log.good 2; rm -rf solid postProcessing [1-9]*; done
cd ..; rm -rf blast; blastDone; snap ../before; cp constant/fsiProperties ../fp; sed -i "0,/^\( *\)maxIter .*/s//\1maxIter 0;/" constant/fsiProperties; run 60 cellBlastFoam -overwrite > log.ow 2>&1; fatal log.ow 1; echo "-overwrite refused; gone: $(gone ../before | tr '\n' ' ')"; ls -a . solid | tr '\n' ' '
