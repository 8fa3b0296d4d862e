#!/bin/bash
# b35 (class 1, an indentation restart after the mesh changed through a SYMBOLIC LINK): constant/cell.msh a link to $W/meshA.msh; the run (10x finer steps) SIGKILLed after its first checkpoint; the link retargeted to (a) another mesh ($W/meshB.msh, nucleusSize 0.7e-6): refused naming the mesh, nothing changed; (b) a byte-identical copy of meshA elsewhere: continues to its end?
. "$(dirname "$0")/../lib.sh"
ind; mv constant/cell.msh $W/meshA.msh; ln -s $W/meshA.msh constant/cell.msh; mkdir -p $W/mb; cp -r system constant $W/mb/; rm $W/mb/constant/cell.msh; (cd $W/mb && sete system/cellMeshDict nucleusSize 0.7e-6 && cellMesh > log.cm 2>&1; echo "   meshB: rc=$?"); cp $W/mb/constant/cell.msh $W/meshB.msh; cp $W/meshA.msh $W/meshA2.msh
sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cellIndentationFoam > log.first 2>&1 & p=$!; waitFor 120 test -f postProcessing/indentation/restart.h5; sleep 1; kill -KILL $p; wait $p 2>/dev/null; latest; echo "   killed: force rows $(grep -vc '^#' postProcessing/indentation/force.dat)"; sums > ../before
ln -sfn $W/meshB.msh constant/cell.msh; tryf "(a) link to another mesh" cellIndentationFoam; nochange ../before
ln -sfn $W/meshA2.msh constant/cell.msh; tryf "(b) link to an identical copy" cellIndentationFoam; forceOk postProcessing/indentation/force.dat; tail -2 $W/try.log | cut -c1-120
