#!/bin/bash
# x71: two ./Allrun of the same blast preview copy started at the SAME instant (a double click, two terminals): exactly one runs, the other refused before touching anything; the results of the one complete?
. "$(dirname "$0")/../lib.sh"
prev; (./Allrun $PREV -endTime 2e-9 > ../log.1 2>&1; echo "first exit $?" > ../rc1) & (./Allrun $PREV -endTime 2e-9 > ../log.2 2>&1; echo "second exit $?" > ../rc2) & wait
cat ../rc1 ../rc2; for l in ../log.1 ../log.2; do echo "$l: $(head -2 $l | tr '\n' ' ' | cut -c1-200) ... $(tail -1 $l | cut -c1-100)"; done; echo "times: $(ls -d [1-9]* | tr '\n' ' ') lock: $(lockOf)"
