#!/bin/bash
# o08: cellMesh re-run with a bad cellMeshDict over a good constant/cell.msh
. "$(dirname "$0")/../lib.sh"
ind; md5sum constant/cell.msh > ../m; setd system/cellMeshDict nucleusVolumeFraction 1.5
cellMesh 2>&1 | grep -i -A3 error | head; echo "rc=${PIPESTATUS[0]}"; md5sum -c ../m
