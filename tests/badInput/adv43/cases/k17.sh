#!/bin/bash
# k17 (class 2, riemannError's and setRiemannProblem's folders): sodIdealGas run (rhoRiemannFoam) and riemannError -latestTime; the user's notes.md and profile.dat.mine in postProcessing/riemannError/ (and its time subfolder if any); riemannError again; then rhoRiemannFoam -overwrite and setRiemannProblem -overwrite: kept or refused by name?
. "$(dirname "$0")/../lib.sh"
sodDone; run 60 riemannError -latestTime > log.re1 2>&1; fatal log.re1 2; D=postProcessing/riemannError; echo "   $D: $(find $D | head -8 | tr '\n' ' ')"; d=$(dirname $(find $D -name 'profile.dat' | head -1) 2>/dev/null); d=${d:-$D}; mkdir -p $d
echo "# k17 riemann notes" > $d/notes.md; echo "k17 profile mine" > $d/profile.dat.mine
run 60 riemannError -latestTime > log.re2 2>&1; fatal log.re2 2; kept "k17 riemann notes" "k17 profile mine"
restart0; sums > ../s; tryf "rhoRiemannFoam -overwrite" rhoRiemannFoam -overwrite; grep -a 'postProcessing' $W/try.log | grep -v '^-->' | head -3 | cut -c1-160; kept "k17 riemann notes" "k17 profile mine"
tryf "setRiemannProblem -overwrite" setRiemannProblem -overwrite; kept "k17 riemann notes" "k17 profile mine"
