#!/bin/bash
# k20: blast: solidProbes row value replaced by nan, planeWave
. "$(dirname "$0")/../lib.sh"
blastDone; f=$(ls postProcessing/solidProbes/0/*); sed -i '$ s/^\(\S*\)\s\+\S\+/\1 nan/' $f; tail -1 $f | cut -c1-80
planeWave -Z 20e-6 -dz 50e-9 > log.pw 2>&1; rc=$?; grep -i -A3 "error\|Traceback\|nan" log.pw | head; tail -3 log.pw; echo "rc=$rc"
