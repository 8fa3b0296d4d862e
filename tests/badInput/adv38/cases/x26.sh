#!/bin/bash
# x26: cellMeshDict: an entry of the top level given in the file and again in a file the user #includes AFTER it (nucleusSize 0.5e-6, then #include "sizes" with nucleusSize 0.4e-6) and BEFORE it: refused naming both places, or one taken silently? (cellMesh on the blast base)
. "$(dirname "$0")/../lib.sh"
blast; rm -f system/cellMeshDict.allrun; sed -i '/#sinclude "cellMeshDict.allrun"/d' system/cellMeshDict; grep -n "nucleusSize" system/cellMeshDict | head -2; cp system/cellMeshDict ../cm0; md5sum constant/cell.msh > ../m0
echo "nucleusSize 0.4e-6;" > system/sizes; echo '#include "sizes"' >> system/cellMeshDict; try "include after" cellMesh; md5sum -c ../m0
cp ../cm0 system/cellMeshDict; sed -i '0,/^nucleusSize/s//#include "sizes"\nnucleusSize/' system/cellMeshDict; try "include before" cellMesh; md5sum -c ../m0
