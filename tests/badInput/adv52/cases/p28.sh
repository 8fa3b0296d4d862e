#!/bin/bash
# CASETIMEOUT=900
# p28 (new, class 2/5: solidToFoam and cellMesh SIGKILLed while writing, then their outputs used; the Allrun's kill during
# cellMesh was tried (w114), solidToFoam's never): (a) solidToFoam on bd SIGKILLed at 0.3, 0.6, 1.2 s, then foamToVTK
# -region solid -latestTime and a second solidToFoam; (b) cellMesh in the quarter's smoke folder (qm) SIGKILLed at 2, 5,
# 10 s: what is left under the final names (cell.msh, fluid.msh: cut files ending before $EndElements?)
# Expected: nothing cut left under a final name (atomic writes), or the next tool names it as incomplete; a cut file
# read as good = DATALOSS/SILENT.
. "$(dirname "$0")/../lib.sh"
bd; C=$PWD; for t in 0.3 0.6 1.2; do rm -rf constant/solid [0-9]*/solid; solidToFoam solid/solid.h5 > $W/s.log 2>&1 & p=$!; sleep $t; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null
  echo "   killed at $t s: constant/solid: $(find constant/solid -type f 2>/dev/null | wc -l) files, times with solid/: $(ls -d [0-9]*/solid 2>/dev/null | tr '\n' ' '), tmp: $(find . -name '*.tmp*' -o -name '.*.tmp' 2>/dev/null | head -3 | tr '\n' ' ') | lock: $(lockOf | cut -c1-50)"
  tryt 120 "   (a) foamToVTK -region solid -latestTime after the kill at $t s" foamToVTK -region solid -latestTime; echo "      said: $(grep -a -m1 -i 'fatal\|error' $W/try.log | cut -c1-200)"
  rm -f .runLock; tryt 120 "   (a) solidToFoam again" solidToFoam solid/solid.h5; echo "      $(tail -1 $W/try.log | cut -c1-150)"; done
cd $W; qm; for t in 2 5 10; do rm -f constant/cell.msh constant/fluid.msh; rm -rf constant/polyMesh; cellMesh > $W/c.log 2>&1 & p=$!; sleep $t; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null; rm -f .runLock
  echo "   cellMesh killed at $t s: $(ls -la constant/ 2>/dev/null | grep -v '^total\|^d' | awk '{print $5, $9}' | tr '\n' ' ' | cut -c1-250) | last log line: $(tail -1 $W/c.log | cut -c1-100)"
  for f in constant/cell.msh constant/fluid.msh; do [ -f $f ] && echo "      $f ends with: $(tail -c 40 $f | tr '\n' ' ')"; done; done
