#!/bin/bash
# x69: cellMeshDict fluid / mode entries at edges for the quarter3D mode never tried: azimuthSize 1e-300, azimuthSize 1 (one element per quarter turn), mode quarter3D with contactRadius 0: refused with the range / meshed sensibly, within 60 s?
. "$(dirname "$0")/../lib.sh"
blast; rm -f system/cellMeshDict.allrun; md5sum constant/cell.msh > ../m0
each system/cellMeshDict "azimuthSize 1e-300" "azimuthSize 1" "contactRadius 0" -- cellMesh
md5sum -c ../m0 2>&1 | tail -1
