#!/bin/bash
# b34 (class 2+4, cellMesh's outputs: a link, a read-only folder, a unicode -dict): (a) constant/cell.msh a SYMBOLIC LINK to the user's own mesh outside the case; cellMesh: the link replaced by the new mesh (the user's file untouched) or refused naming it, never written through; (b) constant/ read-only: an error naming the file, no crash; (c) cellMesh -dict "system/cellMeshDict.ünï" (a copy) runs or refuses naming it?
. "$(dirname "$0")/../lib.sh"
ind; mkdir -p $W/mine; cp constant/cell.msh $W/mine/cell.msh; echo "// b34 my mesh notes" >> $W/mine/cell.msh; md5sum $W/mine/cell.msh > ../m; rm constant/cell.msh; ln -s $W/mine/cell.msh constant/cell.msh
tryf "(a) cell.msh a link" cellMesh; echo "   cell.msh: $(test -L constant/cell.msh && echo "link -> $(readlink constant/cell.msh)" || echo 'a file'); the user's mesh: $(md5sum -c ../m 2>&1 | awk '{print $2}')"
rm -f constant/cell.msh; cellMesh > log.cm0 2>&1; md5sum constant/cell.msh > ../m2; ro constant; tryf "(b) read-only constant/" cellMesh; umount constant; echo "   cell.msh: $(md5sum -c ../m2 2>&1 | awk '{print $2}'); constant/: $(ls -a constant | tr '\n' ' ')"
cp system/cellMeshDict "system/cellMeshDict.ünï"; rm -f log.cellMesh; tryf "(c) -dict unicode" cellMesh -dict "system/cellMeshDict.ünï"
