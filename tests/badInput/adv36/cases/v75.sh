#!/bin/bash
# v75: duplicates: constant/indenterProperties maxDeltaT given a second time through an #include file (our own dictionary)
. "$(dirname "$0")/../lib.sh"
ind; echo 'maxDeltaT 0.05;' > constant/stepOverride; echo '#include "stepOverride"' >> constant/indenterProperties; grep -n "maxDeltaT\|include" constant/indenterProperties | cut -c1-80
timeout 100 cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"; grep -a -i "maxDeltaT" log.run | head -2 | cut -c1-200; echo "force.dat rows: $(grep -vc '^#' postProcessing/indentation/force.dat)"
