#!/bin/bash
# CASETIMEOUT=900
# j01 (class 5, fix19e's checkRestartState (adv48a h01 (h), (i)) varied, serial): the finished preview bd, startFrom latestTime,
# endTime 3e-9, one value of a binary restart field set, the marker intact, `cellBlastFoam -acceptEdited` (the check's
# premise: the digest check waived): (a) rhoE[5] 0 (e = -|U|^2/2), (b) rhoE[5] -1e308, (c) rhoU[15] 1e300 (U above
# velocityMax), (d) rhoU[16] NaN (a component), (e) rho[5] 4.9e-324 (subnormal), (f) rho[5] 1e300, (g) rhoE[5] inf,
# (h) rho[5] -0 (negative zero), (i) rho's interface patch value[0] NaN (the boundary field only), (j) the same without
# -acceptEdited, (k) the oldest time: 2e-09 moved away, 1e-09/rho[5] NaN, restart (latestTime = 1e-09) -acceptEdited,
# (l) the oldest time damaged, the restart from the newest (2e-09, undamaged, no -acceptEdited): must run to 3e-09.
# Each of (a)-(k) refused rc 1 naming time, cell (or patch), field and why; never a signal, never a run from the state.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cp -a . ../keep
one() { local l=$1; shift; tryt 90 "$l" cellBlastFoam "$@"; echo "   sig lines: $(sig) | times: $(ls -d [0-9]* *incomplete* 2>/dev/null | tr '\n' ' ')"; echo "   msg: $(msg 6)"; cd $W; rm -rf blast; cp -a keep blast; cd blast; }
setb 2e-09/rhoE 5 0; one "(a) rhoE[5] 0, -acceptEdited" -acceptEdited
setb 2e-09/rhoE 5 -1e308; one "(b) rhoE[5] -1e308, -acceptEdited" -acceptEdited
setb 2e-09/rhoU 15 1e300; one "(c) rhoU[15] 1e300, -acceptEdited" -acceptEdited
setb 2e-09/rhoU 16 nan; one "(d) rhoU[16] NaN, -acceptEdited" -acceptEdited
setb 2e-09/rho 5 4.9e-324; one "(e) rho[5] 4.9e-324, -acceptEdited" -acceptEdited
setb 2e-09/rho 5 1e300; one "(f) rho[5] 1e300, -acceptEdited" -acceptEdited
setb 2e-09/rhoE 5 inf; one "(g) rhoE[5] inf, -acceptEdited" -acceptEdited
setb 2e-09/rho 5 -0.0; one "(h) rho[5] -0, -acceptEdited" -acceptEdited
setbb 2e-09/rho interface 0 nan; one "(i) rho interface value[0] NaN, -acceptEdited" -acceptEdited
setbb 2e-09/rho interface 0 nan; one "(j) rho interface value[0] NaN, no -acceptEdited"
mv 2e-09 ../t2; setb 1e-09/rho 5 nan; one "(k) oldest time 1e-09 (2e-09 moved away): rho[5] NaN, -acceptEdited" -acceptEdited; rm -rf ../t2
setb 1e-09/rho 5 nan; tryt 300 "(l) 1e-09/rho[5] NaN, restart from 2e-09" cellBlastFoam; echo "   sig lines: $(sig) | times: $(ls -d [0-9]* | tr '\n' ' ')"; cont; after
