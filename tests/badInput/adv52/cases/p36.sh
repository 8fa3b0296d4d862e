#!/bin/bash
# CASETIMEOUT=600
# p36 (new, class 2: a FILE that is a symbolic link into another case, written by our tools): the finished preview A (bd)
# and B (A's inputs copied) whose (a) constant/cell.msh is a link to A's constant/cell.msh: B's cellMesh with another
# -cell (cellMeshDict.allrun nucleusSize/cytoplasmSize 0.7e-6); (b) constant/thermophysicalProperties a link to A's:
# nothing of ours writes it (control); (c) system/controlDict.allrun a link to A's: B's ./Allrun -noRun (which writes
# controlDict.allrun). Expected: the link replaced by B's own file or refused; A's file changed through the link = DATALOSS.
. "$(dirname "$0")/../lib.sh"
bd; A=$PWD; sums > $W/sA
mkB() { cd $W; rm -rf B; mkdir B; cd B; cp -r $A/0.orig $A/system .; mkdir constant; for f in $A/constant/*; do [ "$(basename $f)" = polyMesh ] || cp -r $f constant/; done; cp -r $A/constant/polyMesh constant/; }
st() { cd $A; echo "   A changed: $(changed $W/sA | cut -c1-300)"; cd $W/B; echo "   B's link now: $(ls -la $1 | awk '{print $1, $NF}')"; }
mkB; rm constant/cell.msh; ln -s $A/constant/cell.msh constant/cell.msh; sed -i '/^nucleusSize\|^cytoplasmSize/d' system/cellMeshDict.allrun; printf 'nucleusSize 0.7e-6;\ncytoplasmSize 0.7e-6;\n' >> system/cellMeshDict.allrun
tryt 300 "(a) B's cellMesh, constant/cell.msh a link to A's" cellMesh; echo "   said: $(msg 2 | cut -c1-200)"; st constant/cell.msh
cd $A; sums > $W/sA; cp $ROOT/tutorials/blast/axisymmetricPreview/Allrun $W/Allrun.tut
mkB; cp $W/Allrun.tut Allrun; rm -f system/controlDict.allrun; ln -s $A/system/controlDict.allrun system/controlDict.allrun; rm -f .allrunOptions
tryt 400 "(c) B's ./Allrun -noRun, system/controlDict.allrun a link to A's" ./Allrun -noRun -noPlots -noVTK -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 5e-9; echo "   said: $(grep -a -m2 -i 'error\|link' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-250)"; st system/controlDict.allrun
