#!/bin/bash
# CASETIMEOUT=900
# h01 (class 5, adv47a f07 varied: one value of a committed restart field damaged in a parse-valid way, binary fields (the
# preview writes binary), the marker intact; the finished preview, startFrom latestTime, endTime 3e-9): (a) rho[5] NaN,
# (b) rho[5] -1000, (c) rho[5] 0 (one cell), (d) rho cut to half its size, (e) rhoE[5] inf, (f) rhoU[15] 1e308, (g) rho[5]
# -1000 with -acceptEdited, (h) rho[5] 1e-290 with -acceptEdited, (i) rho[5] NaN with -acceptEdited, (j) 1e-09/rho zeroed
# (64 B) and the restart from 1e-09 (startFrom startTime, startTime 1e-09). Each refused naming the file (digest) or the
# value's range (with -acceptEdited); never a sigFpe nor a run from the damaged state. 60 s each.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cp -a . ../keep
one() { local l=$1; shift; tryt 60 "$l" cellBlastFoam "$@"; echo "   $(grep -a -m1 'Restarting from' $W/try.log | cut -c1-90) | sig lines: $(sig) | times: $(ls -d [0-9]* *incomplete* 2>/dev/null | tr '\n' ' ')"; cd $W; rm -rf blast; cp -a keep blast; cd blast; }
setb 2e-09/rho 5 nan; one "(a) rho[5] NaN"
setb 2e-09/rho 5 -1000; one "(b) rho[5] -1000"
setb 2e-09/rho 5 0; one "(c) rho[5] 0"
cutf 2e-09/rho 50; one "(d) rho cut to half"
setb 2e-09/rhoE 5 inf; one "(e) rhoE[5] inf"
setb 2e-09/rhoU 15 1e308; one "(f) rhoU[15] 1e308"
setb 2e-09/rho 5 -1000; one "(g) rho[5] -1000, -acceptEdited" -acceptEdited
setb 2e-09/rho 5 1e-290; one "(h) rho[5] 1e-290, -acceptEdited" -acceptEdited
setb 2e-09/rho 5 nan; one "(i) rho[5] NaN, -acceptEdited" -acceptEdited
sed -i 's/^startFrom .*/startFrom startTime;/; s/^startTime .*/startTime 1e-09;/' system/controlDict; grep -a '^start' system/controlDict | tr '\n' ' '; dmgf 1e-09/rho; one "(j) 1e-09/rho zeroed, restart from 1e-09"
