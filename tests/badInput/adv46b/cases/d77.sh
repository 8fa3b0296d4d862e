#!/bin/bash
# d77 (class 3, d67 with a short run to count the race: the finished preview with a stale .runLock of this host (a dead process, executable solidToFoam, this case), two solidToFoam started at the same instant, 20 trials): in no trial may both take the stale lock over ("Removing the stale run lock" twice).
. "$(dirname "$0")/../lib.sh"
bd; n=0; for t in $(seq 20); do rm -rf constant/solid [0-9]*/solid; bash -c "exit 0" & dead=$!; wait $dead
  printf "pid %s\nhost %s\nexecutable solidToFoam\nstarted 2026-12-05T10:00:00\ncase %s\n" $dead $(hostname) $PWD > .runLock
  solidToFoam solid/solid.h5 > ../a 2>&1 & a=$!; solidToFoam solid/solid.h5 > ../b 2>&1 & b=$!; wait $a; ra=$?; wait $b; rb=$?
  k=$(grep -l "Removing the stale" ../a ../b | wc -l); [ $k -ge 2 ] && { n=$((n+1)); echo "   both: $(grep -a -h -A1 "FATAL" ../a ../b | tail -1 | cut -c1-200)"; }; echo "trial $t: rc $ra $rb, stale taken over by $k"; done; echo "both took the stale lock over in $n of 20 trials"
