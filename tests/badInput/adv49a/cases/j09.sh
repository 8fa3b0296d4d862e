#!/bin/bash
# CASETIMEOUT=900
# j09 (class 5/4, the solid's restart state: j06's n/r part and checkRestartState's premise beyond the fluid fields): bd,
# startFrom latestTime, endTime 3e-9, one entry of 2e-09/uniform/solidState (or fsiState) edited, `cellBlastFoam
# -acceptEdited`: solidState (a) h5Step 2147483648, (b) h5Step 9223372036854775808, (c) h5Step -1, (d) h5Step 5 (solid.h5
# has 2 steps), (e) steps 2147483648, (f) dt nan, (g) stableDt 0, (h) time 3e-09 (not the directory's time), (i) the first
# interfaceForce value nan; (j) (a) without -acceptEdited. Each refused rc 1 naming the file, the entry and why (or the
# digest without -acceptEdited); never a signal, never a run from a state that is not the run's.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cp -a . ../keep; S=2e-09/uniform/solidState
one() { local l=$1; shift; tryt 120 "$l" cellBlastFoam "$@"; echo "   sig: $(sig) | times: $(ls -d [0-9]* | tr '\n' ' ') | msg: $(msg 4 | cut -c1-600)"; cd $W; rm -rf blast; cp -a keep blast; cd blast; }
for e in "h5Step 2147483648" "h5Step 9223372036854775808" "h5Step -1" "h5Step 5" "steps 2147483648" "dt nan" "stableDt 0" "time 3e-09"; do sete $S ${e%% *} ${e#* }; one "solidState $e, -acceptEdited" -acceptEdited; done
/usr/bin/python3 - $S <<'P'
import sys, re
f = sys.argv[1]; t = open(f).read(); k = t.find('interfaceForce'); k = t.find('(', k) + 1; m = re.compile(r'[-+0-9.eE]+').search(t, k)
open(f, 'w').write(t[:m.start()] + 'nan' + t[m.end():]); print('   %s: interfaceForce[0] %s -> nan' % (f, m.group()))
P
one "solidState interfaceForce[0] nan, -acceptEdited" -acceptEdited
sete $S h5Step 2147483648; one "solidState h5Step 2147483648, no -acceptEdited"
