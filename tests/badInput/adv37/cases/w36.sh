#!/bin/bash
# w36: ind killed at 2 s (in row A), a row inserted BEFORE the running one (A0 load 0.1e-6 0.3e-6), restart: refused?
. "$(dirname "$0")/../lib.sh"
indKilled 2; tail -1 postProcessing/indentation/force.dat | cut -c1-120; sed -i 's/^    (A   load    0.3e-6  0.3e-6)/    (A0  load    0.1e-6  0.3e-6)\n    (A   load    0.3e-6  0.3e-6)/' constant/indenterProperties; grep -A3 "^protocol" constant/indenterProperties
run 120 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
