#!/bin/bash
# x14: blast finished to 2 ns: -overwrite from a time that was NOT written (startTime 1.5e-09) and from a negative one (-1e-09): refused naming the start time, nothing moved?
. "$(dirname "$0")/../lib.sh"
blastDone; snap ../s0
for t in 1.5e-09 -1e-09; do sed -i "s/^startTime .*/startTime $t;/" system/controlDict; try "startTime $t" cellBlastFoam -overwrite; echo "  lost: $(gone ../s0 | tr '\n' ' ') aside: $(find . -name '.*overwritten*' | tr '\n' ' ') times: $(ls -d [0-9]* | tr '\n' ' ')"; done
