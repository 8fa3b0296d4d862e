#!/bin/bash
# x13: blast finished to 2 ns: -overwrite from the LATEST time (startTime 2e-09, startFrom startTime, endTime 3e-9): refused with a sensible way out (as the middle time), or run? nothing lost either way?
. "$(dirname "$0")/../lib.sh"
blastDone; snap ../s0; sed -i 's/^startTime .*/startTime 2e-09;/' system/controlDict; blastEnd 3e-9 1e-9
run 120 cellBlastFoam -overwrite > log.o 2>&1; fatal log.o 10; tail -1 log.o; echo "lost: $(gone ../s0 | tr '\n' ' ')"; ls -d [1-9]* | tr '\n' ' '; echo; echo "aside: $(find . -name '.*overwritten*' | tr '\n' ' ')"
