#!/bin/bash
# k01: ind: solid.h5 truncated to 60 %, solidToFoam
. "$(dirname "$0")/../lib.sh"
indDone; H5=postProcessing/indentation/solid.h5; truncate -s $(($(stat -c%s postProcessing/indentation/solid.h5)*60/100)) postProcessing/indentation/solid.h5
solidToFoam $H5 > log.s 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.s | head -8; tail -2 log.s; echo "rc=$rc"
