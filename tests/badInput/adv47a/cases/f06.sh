#!/bin/bash
# f06 (class 3, adv46b d67/d77 varied: a stale .runLock of this host (a dead process) raced by two DIFFERENT tools started
# at the same instant): (a) the finished preview, restart to 3e-9 (cellBlastFoam, SIGKILLed at 10 s) and solidToFoam,
# 8 trials; (b) the same case, planeWave (Python: neuronFsi.caseLock) and solidToFoam (C++: caseLock.H), 8 trials;
# (c) the smoke indentation, cellMesh and cellIndentationFoam (SIGKILLed at 10 s), 6 trials. In no trial may both take the
# stale lock over ("Removing the stale run lock" twice); the other refused naming the one that runs.
. "$(dirname "$0")/../lib.sh"
stale() { bash -c "exit 0" & local dead=$!; wait $dead; printf "pid %s\nhost %s\nexecutable %s\nstarted 2026-12-05T10:00:00\ncase %s\n" $dead $(hostname) $1 $PWD > .runLock; }
race() { local tag=$1 n=$2 ca=$3 cb=$4 k both=0; for t in $(seq $n); do cd $W; rm -rf c; cp -a keep c; cd c; stale $5
  bash -c "$ca" > ../a 2>&1 & local a=$!; bash -c "$cb" > ../b 2>&1 & local b=$!; wait $a; local ra=$?; wait $b; local rb=$?
  k=$(grep -l "Removing the stale" ../a ../b | wc -l); [ $k -ge 2 ] && both=$((both+1))
  echo "$tag trial $t: rc $ra $rb, stale taken over by $k | A: $(grep -a -m1 -i 'stale\|in use\|lock' ../a | cut -c1-110) | B: $(grep -a -m1 -i 'stale\|in use\|lock' ../b | cut -c1-110)"; done
  echo "$tag: both took the stale lock over in $both of $n trials"; }
bd; rs; rm -f .runLock; cp -a . ../keep
race "(a) cellBlastFoam + solidToFoam" 8 "timeout -s KILL 10 cellBlastFoam" "solidToFoam solid/solid.h5" cellBlastFoam
race "(b) planeWave + solidToFoam" 8 "planeWave" "solidToFoam solid/solid.h5" planeWave
cd $W; rm -rf keep c; ind; cp -a . ../keep
race "(c) cellMesh + cellIndentationFoam" 6 "cellMesh" "timeout -s KILL 10 cellIndentationFoam" cellMesh
