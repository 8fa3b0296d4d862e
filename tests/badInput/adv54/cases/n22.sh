#!/bin/bash
# CASETIMEOUT=600
# n22 (new, class 3: two writers at once in the verification cases, through the tools no pass ran together): the sod tube
# finished (sodDone): (a) two riemannError at once (the second 0.05 s later); (b) riemannError while rhoRiemannFoam
# restarts (endTime x1.2) in the same case; (c) setRiemannProblem while rhoRiemannFoam restarts (it rewrites 0/ under a
# run that started from the latest time). Expected: one writer per case (the second refused naming the first) or both
# whole; postProcessing/riemannError/<t>/ of one run, whole; 0/ kept under a running restart, or refused.
. "$(dirname "$0")/../lib.sh"
sodDone; riemannError > $W/r1.log 2>&1 & p=$!; sleep 0.05; riemannError > $W/r2.log 2>&1; r2=$?; wait $p; r1=$?
echo "   (a) rc $r1 / $r2 | 1: $(grep -a -m1 -A2 'FATAL\|rror' $W/r1.log | tr -s ' ' | tr '\n' ' ' | cut -c1-200) | 2: $(grep -a -m1 -A2 'FATAL\|rror' $W/r2.log | tr -s ' ' | tr '\n' ' ' | cut -c1-250) | $(ls -R postProcessing/riemannError | tr '\n' ' ' | cut -c1-200)"
sed -i 's/^endTime .*/endTime 0.014;/; s/^writeInterval .*/writeInterval 0.007;/' system/controlDict; grep '^endTime\|^startFrom\|^writeInterval' system/controlDict | tr '\n' ' '; echo
rhoRiemannFoam > $W/run.log 2>&1 & p=$!; sleep 0.3; tryt 120 "(b) riemannError while rhoRiemannFoam restarts" riemannError; echo "   said: $(say 2 | cut -c1-250)"
touch $W/stamp; tryt 120 "(c) setRiemannProblem while rhoRiemannFoam restarts" setRiemannProblem; echo "   said: $(say 2 | cut -c1-250) | 0/ changed: $(find 0 -newer $W/stamp -type f | tr '\n' ' ')"
wait $p; echo "   the restart: rc $? End $(grep -a -c '^End' $W/run.log)"
