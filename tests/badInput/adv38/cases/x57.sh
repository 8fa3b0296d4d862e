#!/bin/bash
# x57: cellMeshDict (axisymmetric cell of the blast base) at geometric edges never tried: membraneThickness = cellHeight/2 (membrane fills the cell), contactRadius = cellDiameter/2 (contact over the whole base), contactDepth 8e-6 (> cellHeight), nucleusVolumeFraction 1e-9 (a nucleus far below one element), membraneLayers 40 (40 layers in 0.2 um): each refused naming the entry and range, or meshed sensibly (no crash, no hang)?
. "$(dirname "$0")/../lib.sh"
blast; md5sum constant/cell.msh > ../m0
each system/cellMeshDict "membraneThickness 3.95e-6" "contactRadius 8.4e-6" "contactDepth 8e-6" "nucleusVolumeFraction 1e-9" "membraneLayers 40" -- cellMesh
md5sum -c ../m0 2>&1 | tail -1
