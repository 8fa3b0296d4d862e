#!/bin/bash
# CASETIMEOUT=900
# j10 (class 6, j07's cellBlastFoam edges redone: j07 (a) estimated 1 step, (b), (c) had deltaT above maxDeltaT): the
# preview with deltaT = maxDeltaT = 1e-12 s: (a) endTime 2e-11 (20 steps): maxSteps 19, 20, 21; (b) endTime 3e-11
# (3e-11/1e-12 = 29.999999999999996 in doubles: 30 steps): maxSteps 29, 30, 31; (c) endTime 3e-12, writeInterval 1e-12
# (2.9999999999999996 writes: 3): maxWrites 2, 3, 4. The count below the estimate refused naming it whole, the others run
# (killed at 45 s or end); the estimate is a lower bound (the Courant limit left out), so an accepted run may take more.
. "$(dirname "$0")/../lib.sh"
blast; rm -f .runLock; sete system/controlDict maxDeltaT 1e-12; grep -a "^deltaT\|^maxDeltaT" system/controlDict | tr '\n' ' '; echo
try3() { local l=$1 k=$2; shift 2; for m in "$@"; do sed -i "/^$k /d" system/controlDict; echo "$k $m;" >> system/controlDict; tryt 45 "$l: $k $m" cellBlastFoam; echo "   sig: $(sig) | steps run: $(grep -a -c '^Time = ' $W/try.log) | times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')| msg: $(msg 2 | cut -c1-260)"; rm -rf postProcessing solid [1-9]* .runLock; done; sed -i "/^$k /d" system/controlDict; }
blastEnd 2e-11 1e-11; try3 "(a) 2e-11 in steps of 1e-12" maxSteps 19 20 21
blastEnd 3e-11 1e-11; try3 "(b) 3e-11 in steps of 1e-12" maxSteps 29 30 31
blastEnd 3e-12 1e-12; try3 "(c) writes every 1e-12 s to 3e-12" maxWrites 2 3 4
