#!/bin/bash
# CASETIMEOUT=600
# n07 (new, class 2/3: a mesh folder shared between cases through a link, written by our mesher): A = bd (finished
# preview); B = a second case made from A's system/ and 0/ with (a) constant/ a symbolic link to A's constant/ (a user
# sharing the meshes and materials between two variants), (b) only constant/cell.msh a link to A's cell.msh; in B,
# membraneLayers 2 in system/cellMeshDict.allrun and `cellMesh`. Then A's restart to 3e-9. Expected: cellMesh in B
# refuses to write through a link leaving the case (as the solvers' output folders since fix19j), A's cell.msh kept; a
# replaced A/constant/cell.msh (A's restart then refused, its mesh gone) = DATALOSS.
. "$(dirname "$0")/../lib.sh"
bd; A=$PWD; md5sum constant/cell.msh > $W/m0; cd $W; mkdir B; cp -r $A/system $A/0 B/; ln -s $A/constant B/constant; cd B
mset membraneLayers 2; tryt 300 "(a) cellMesh in B, constant/ a link to A's" cellMesh; echo "   said: $(say 2 | cut -c1-250) | A's cell.msh: $(md5sum -c $W/m0 2>&1 | tr '\n' ' ')"
cd $A; md5sum -c $W/m0 > /dev/null 2>&1 || { rs; rm -f .runLock; tryt 300 "   A's restart to 3e-9 after" cellBlastFoam; echo "   said: $(say 2 | cut -c1-250)"; }
cd $W; rm -rf blast B; bd; A=$PWD; cd $W; mkdir -p B/constant; cp -r $A/system $A/0 B/; cp $A/constant/{fsiProperties,solidProperties,thermophysicalProperties,dynamicMeshDict} B/constant/; cp -r $A/constant/polyMesh B/constant/; ln -s $A/constant/cell.msh B/constant/cell.msh; cd B
mset membraneLayers 2; tryt 300 "(b) cellMesh in B, constant/cell.msh a link to A's" cellMesh; echo "   said: $(say 2 | cut -c1-250) | A's cell.msh: $(cd $A; md5sum -c $W/m0 2>&1 | tr '\n' ' ') | B's cell.msh: $(stat -c %F constant/cell.msh)"
