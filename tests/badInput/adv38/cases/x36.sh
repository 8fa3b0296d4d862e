#!/bin/bash
# x36: blast finished to 2 ns, then 0/p converted to BINARY (foamFormatConvert -time 0: the user's initial conditions rewritten, same values and conditions), restart to 3 ns: accepted (nothing changed), not refused as a changed initial condition?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../conv; (cd ../conv && setd system/controlDict writeFormat binary && foamFormatConvert -time 0 > log.conv 2>&1 || tail -3 log.conv); cp ../conv/0/p 0/p; grep -a -m1 format 0/p
try "0/ binary" cellBlastFoam; echo "times: $(ls -d [1-9]* | tr '\n' ' ')"
