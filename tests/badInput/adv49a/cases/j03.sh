#!/bin/bash
# CASETIMEOUT=900
# j03 (class 5, checkRestartState in rhoRiemannFoam, ascii fields): the sod tube run to its end, then its last time made the
# restart (startFrom latestTime, endTime a step later), one value of an ascii field edited, `rhoRiemannFoam -acceptEdited`:
# (a) rho 1e-290, (b) rhoE 0 (e = -|U|^2/2 or 0), (c) rhoU 1e300 (x), (d) rho 4.9e-324, (e) rhoE -1e300, (f) the same as (a)
# without -acceptEdited (the digest). Each refused rc 1 naming the cell, the field and why; never a signal.
. "$(dirname "$0")/../lib.sh"
sodDone; T=$(ls -d [0-9]* | sort -g | tail -1); echo "sod: times $(ls -d [0-9]* | tr '\n' ' '), latest $T; $(grep -a -m1 '^endTime' system/controlDict)"
latest; E=$(/usr/bin/python3 -c "print(repr(float('$T') * 1.01))"); sed -i "s/^endTime .*/endTime $E;/" system/controlDict; rm -f .runLock; cp -a . ../keep
one() { local l=$1; shift; tryt 90 "$l" rhoRiemannFoam "$@"; echo "   sig lines: $(sig) | times: $(ls -d [0-9]* | tr '\n' ' ')"; echo "   msg: $(msg 6)"; cd $W; rm -rf sod; cp -a keep sod; cd sod; }
setv $T/rho 20 1e-290; one "(a) rho[20] 1e-290, -acceptEdited" -acceptEdited
setv $T/rhoE 20 0; one "(b) rhoE[20] 0, -acceptEdited" -acceptEdited
/usr/bin/python3 - $T/rhoU <<'P'
import re, sys
f = sys.argv[1]; s = open(f).read(); k = s.find('(', s.find('internalField')) + 1; m = re.compile(r'\(\s*([-+0-9.eE]+)').search(s, k + 20 * 10)
open(f, 'w').write(s[:m.start(1)] + '1e300' + s[m.end(1):]); print('   %s: a vector x %s -> 1e300' % (f, m.group(1)))
P
one "(c) rhoU x 1e300, -acceptEdited" -acceptEdited
setv $T/rho 20 4.9e-324; one "(d) rho[20] 4.9e-324, -acceptEdited" -acceptEdited
setv $T/rhoE 20 -1e300; one "(e) rhoE[20] -1e300, -acceptEdited" -acceptEdited
setv $T/rho 20 1e-290; one "(f) rho[20] 1e-290, no -acceptEdited"
