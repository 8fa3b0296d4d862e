#!/bin/bash
# v76: duplicates: constant/fsiProperties coupling maxIter given a second time through #include (our own dictionary)
. "$(dirname "$0")/../lib.sh"
blast; echo 'maxIter 1;' > constant/couplingOverride; sed -i 's/^\( *maxIter .*\)$/\1\n        #include "couplingOverride"/' constant/fsiProperties; sed -n '/coupling/,/}/p' constant/fsiProperties | grep -n "maxIter\|include"
cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"; grep -a -i "maxIter\|iterations" log.run | head -2 | cut -c1-200
