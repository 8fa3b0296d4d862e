#!/bin/bash
# d76 (class 3, d67 with restarts: the killed smoke indentation (ik) with a stale lock of this host (dead process), two restarts (startFrom latestTime) started at the same instant; 5 trials): each time exactly one continues, the other refused naming it (the lock); never both continuing the same files (force.dat times increasing, no row twice, solid.h5 = xmf).
. "$(dirname "$0")/../lib.sh"
for t in 1 2 3 4 5; do cd $W; rm -rf ind; ik; bash -c "exit 0" & dead=$!; wait $dead
  printf "pid %s\nhost %s\nexecutable cellIndentationFoam\nstarted 2026-12-05T10:00:00\ncase %s\n" $dead $(hostname) $PWD > .runLock
  cellIndentationFoam > ../l1 2>&1 & a=$!; cellIndentationFoam > ../l2 2>&1 & b=$!; wait $a; ra=$?; wait $b; rb=$?
  echo "trial $t: rc $ra, $rb | stale taken over by $(grep -l "Removing the stale" ../l1 ../l2 | xargs -n1 basename | tr "\n" " ")| continuing: $(grep -l "Continuing from" ../l1 ../l2 | xargs -n1 basename | tr "\n" " ")| $(grep -a -h -m1 -A1 "FATAL" ../l1 ../l2 | tail -1 | cut -c1-120)"
  echo "   $(forceOk postProcessing/indentation/force.dat) | solid.h5 $(h5steps postProcessing/indentation/solid.h5), xmf $(xmfsteps postProcessing/indentation/solid.xmf)"; done
