#!/bin/bash
# CASETIMEOUT=900
# k01 (adv49a j03 / fix19f's soundSpeedMax varied at the edge, rhoRiemannFoam, ascii fields): the sod tube run to its end,
# its last time made the restart (startFrom latestTime, endTime 1 % later), cell 20 set to rest (rho 1 kg/m^3, rhoU 0) and
# rhoE at the sound-speed bound computed in doubles by ../ulpEdge.py (c < 1e5 m/s accepted, else refused):
# (a) rhoE 'below' (c = 99999.99999999999 m/s), (b) rhoE 'at' (c = 100000.00000000001 m/s), (c) |U| = 1e5 - 1 ulp with
# rhoE so that e = 1e5 J/kg (velocity bound below), (d) |U| = 1e5 (refused), (e) 'below' in both c and |U| (|U| + c
# 2e5 m/s), (f) the 'at' value only in rhoE's boundary field (left patch value; ignored or refused, no signal),
# (g) 'below' without -acceptEdited (the digest refuses), (h) cell 0 (the first cell, next to the boundary) 'at'.
# Accepted states: the run ends rc 0 or stops with a FatalError naming the state, never a signal; 'at' refused rc 1
# naming the cell, the state and c; the boundary value: no signal.
. "$(dirname "$0")/../lib.sh"
E="$(dirname "$0")/../ulpEdge.py"; read -r _ BELOW _ < <(/usr/bin/python3 $E idealGas 1.0 | grep '^below'); read -r _ AT _ < <(/usr/bin/python3 $E idealGas 1.0 | grep '^at')
echo "edge (ideal gas, rho 1): below $BELOW, at $AT"
sodDone; T=$(ls -d [0-9]* | sort -g | tail -1); echo "sod: times $(ls -d [0-9]* | tr '\n' ' '), latest $T"
latest; Ee=$(/usr/bin/python3 -c "print(repr(float('$T') * 1.01))"); sed -i "s/^endTime .*/endTime $Ee;/" system/controlDict; rm -f .runLock; cp -a . ../keep
one() { local l=$1; shift; tryt 120 "$l" rhoRiemannFoam "$@"; echo "   sig lines: $(sig) | times: $(ls -d [0-9]* | tr '\n' ' ') | End: $(grep -a -c '^End' $W/try.log)"; echo "   msg: $(msg 6)"
  local L=$(ls -d [0-9]* | sort -g | tail -1); [ "$L" != "$T" ] && echo "   $L: nan/inf in rho, p: $(grep -a -c -i 'nan\|inf' $L/rho $L/p 2>/dev/null | tr '\n' ' ')"; cd $W; rm -rf sod; cp -a keep sod; cd sod; }
rest() { setv $T/rho $1 1; fset $T/rhoU internal $1 $2 0 0; setv $T/rhoE $1 $3; }
rest 20 0 $BELOW; one "(a) cell 20 rho 1, U 0, rhoE $BELOW (c just below 1e5 m/s), -acceptEdited" -acceptEdited
rest 20 0 $AT; one "(b) cell 20 rho 1, U 0, rhoE $AT (c just above 1e5 m/s), -acceptEdited" -acceptEdited
UB=99999.99999999999; eU=$(/usr/bin/python3 -c "print(repr(1e5 + 0.5*$UB*$UB))"); rest 20 $UB $eU; one "(c) cell 20 rho 1, rhoU ($UB 0 0), rhoE $eU, -acceptEdited" -acceptEdited
eU=$(/usr/bin/python3 -c "print(repr(1e5 + 0.5*1e5*1e5))"); rest 20 100000.0 $eU; one "(d) cell 20 rho 1, rhoU (1e5 0 0), rhoE $eU, -acceptEdited" -acceptEdited
eU=$(/usr/bin/python3 -c "print(repr($BELOW + 0.5*$UB*$UB))"); rest 20 $UB $eU; one "(e) cell 20 rho 1, rhoU ($UB 0 0), rhoE $eU (c and |U| below), -acceptEdited" -acceptEdited
grep -a -n -A4 'boundaryField' $T/rhoE | head -8 | tr -s ' ' | tr '\n' ' '; echo
/usr/bin/python3 - $T/rhoE $AT <<'P'
import re, sys
f, v = sys.argv[1], sys.argv[2]; s = open(f).read(); k = s.find('boundaryField'); m = re.compile(r'value\s+(uniform\s+[^;]+|nonuniform\s+List<scalar>\s*\d+\s*\(\s*[-+0-9.eE]+)').search(s, k)
if not m: print('   no value entry in the boundary field of %s' % f); sys.exit(0)
t = m.group(1); new = 'uniform ' + v if t.startswith('uniform') else re.sub(r'[-+0-9.eE]+$', v, t)
open(f, 'w').write(s[:m.start(1)] + new + s[m.end(1):]); print('   %s: boundary value %s -> %s' % (f, t[:60].replace('\n', ' '), new[:60].replace('\n', ' ')))
P
one "(f) rhoE's first boundary value $AT, -acceptEdited" -acceptEdited
rest 20 0 $BELOW; one "(g) cell 20 rhoE $BELOW without -acceptEdited"
rest 0 0 $AT; one "(h) cell 0 rho 1, U 0, rhoE $AT, -acceptEdited" -acceptEdited
