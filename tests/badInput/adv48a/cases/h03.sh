#!/bin/bash
# CASETIMEOUT=900
# h03 (class 5, adv47a f08 (a) varied: the sod tube's ascii fields (rhoRiemannFoam, writeFormat ascii), one value of the
# last time changed as text, endTime 1.5x): (a) rho: nan, (b) rho: -1, (c) rho: 0, (d) rho: -0, (e) rho: 4.9e-324,
# (f) rho cut in the middle of its list, (g) rhoE: inf, (h) rhoU: 1e400, (i) p: -1e308, (j) T: nan, (k) rho: -1 with
# -acceptEdited. Each refused naming the file (digest/parse) or the value's range; never a sigFpe, never a run from it.
. "$(dirname "$0")/../lib.sh"
sodDone; t=$(ls -d [0-9]* | sort -g | tail -1); e=$(/usr/bin/python3 -c "print(repr($t*1.5))"); echo "sod last time $t: $(ls $t | tr '\n' ' ')"
sed -i "s/^endTime .*/endTime $e;/; s/^writeInterval .*/writeInterval $e;/" system/controlDict; rm -f .runLock; cp -a . ../sodKeep
one() { local l=$1; shift; tryt 60 "$l" rhoRiemannFoam "$@"; echo "   sig lines: $(sig) | times: $(ls -d [0-9]* *incomplete* 2>/dev/null | tr '\n' ' ')"; cd $W; rm -rf sod; cp -a sodKeep sod; cd sod; }
setv $t/rho 50 nan; one "(a) rho nan"
setv $t/rho 50 -1; one "(b) rho -1"
setv $t/rho 50 0; one "(c) rho 0"
setv $t/rho 50 -0; one "(d) rho -0"
setv $t/rho 50 4.9e-324; one "(e) rho 4.9e-324"
cutf $t/rho 50; one "(f) rho cut"
setv $t/rhoE 50 inf; one "(g) rhoE inf"
setv $t/rhoU 50 1e400; one "(h) rhoU 1e400"
[ -f $t/p ] && { setv $t/p 50 -1e308; one "(i) p -1e308"; }
[ -f $t/T ] && { setv $t/T 50 nan; one "(j) T nan"; }
setv $t/rho 50 -1; one "(k) rho -1, -acceptEdited" -acceptEdited
