#!/bin/bash
# k05: ind: force.dat last line cut in half, restart
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; truncate -s $(($(stat -c%s postProcessing/indentation/force.dat)*97/100)) postProcessing/indentation/force.dat; tail -c 80 postProcessing/indentation/force.dat; echo
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; tail -3 postProcessing/indentation/force.dat
echo "--- rows of force.dat not of 6 columns, and rows around t=2.09:"; grep -v '^#' postProcessing/indentation/force.dat | awk 'NF!=6{print "BAD: " $0}'; grep -n "^2.0[89]\|^2.1 " postProcessing/indentation/force.dat
