#!/bin/bash
# d67 (class 3, a stale lock raced: a lock of this host naming a dead process and cellIndentationFoam, then two cellIndentationFoam started at the same instant; 3 trials): each time exactly one runs (the other refused naming it), never both taking the stale lock over.
. "$(dirname "$0")/../lib.sh"
ind; sed -i "s/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.05e-6/" constant/indenterProperties; cp -a $W/ind $W/base
for t in 1 2 3; do cd $W; rm -rf ind; cp -a base ind; cd ind; bash -c "exit 0" & dead=$!; wait $dead
  printf "pid %s\nhost %s\nexecutable cellIndentationFoam\nstarted 2026-12-05T10:00:00\ncase %s\n" $dead $(hostname) $PWD > .runLock
  cellIndentationFoam > ../l1 2>&1 & a=$!; cellIndentationFoam > ../l2 2>&1 & b=$!; wait $a; ra=$?; wait $b; rb=$?
  echo "trial $t: rc $ra, $rb | $(grep -a -m1 -i "lock\|running\|refus" ../l1 | cut -c1-150) | $(grep -a -m1 -i "lock\|running\|refus" ../l2 | cut -c1-150) | force rows $(grep -vc "^#" postProcessing/indentation/force.dat)"; done; head -3 $W/base/.runLock 2>/dev/null
