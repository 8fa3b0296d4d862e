#!/bin/bash
# k49 (class 3, two cellMesh at once on one case): the quarter (qm) meshed by two cellMesh started 0.1 s apart, one with -dict of a copy whose sizes are other (cell 1 um, water near 0.8 um), 5 trials. Expected: one refused naming the other (one run per case), or the pair constant/cell.msh + constant/fluid.msh always of one run; never a cell.msh of one run beside a fluid.msh of the other without a word.
. "$(dirname "$0")/../lib.sh"
qm; cm > /dev/null; cp constant/cell.msh $W/a.cell; cp constant/fluid.msh $W/a.fluid
cp system/cellMeshDict system/otherDict; sed -i 's/cellMeshDict.allrun/otherDict.allrun/' system/otherDict; sed 's/1.4e-6/1e-6/g; s/nearSize 1e-6/nearSize 0.8e-6/' system/cellMeshDict.allrun > system/otherDict.allrun
cellMesh -dict system/otherDict > $W/b.log 2>&1; echo "   b alone rc=$?"; cp constant/cell.msh $W/b.cell; cp constant/fluid.msh $W/b.fluid
for i in 1 2 3 4 5; do (cellMesh > $W/r1.log 2>&1; echo "rc=$?" >> $W/r1.log) & x=$!; sleep 0.1; (cellMesh -dict system/otherDict > $W/r2.log 2>&1; echo "rc=$?" >> $W/r2.log) & y=$!; wait $x $y
  c=$(cmp -s constant/cell.msh $W/a.cell && echo A || (cmp -s constant/cell.msh $W/b.cell && echo B || echo other)); f=$(cmp -s constant/fluid.msh $W/a.fluid && echo A || (cmp -s constant/fluid.msh $W/b.fluid && echo B || echo other))
  echo "   trial $i: A $(tail -1 $W/r1.log) B $(tail -1 $W/r2.log) | cell.msh $c fluid.msh $f $( [ $c = $f ] && echo consistent || echo MIXED) | $(grep -a -h -i -m1 'lock\|in use\|running' $W/r1.log $W/r2.log | head -1 | cut -c1-150)"; done
