#!/bin/bash
# x29: blast run to 3 ns; the user deletes the latest time 3e-09 (restart from the OLDER 2e-09, whose commit recorded shorter logs) and restarts to 3 ns: accepted, and every log equal to the uninterrupted run's (the rows after 2 ns cut, not doubled)?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 3e-9 1e-9; cellBlastFoam > log.first 2>&1; mkdir ../ref; cp -r postProcessing ../ref/
rm -rf 3e-09; latest; run 120 cellBlastFoam > log.r 2>&1; tail -1 log.r; fatal log.r 4
for f in $(cd ../ref && find postProcessing -type f); do cmp -s ../ref/$f $f && echo "same: $f" || echo "DIFF: $f ($(wc -l < ../ref/$f) vs $(wc -l < $f) lines)"; done
