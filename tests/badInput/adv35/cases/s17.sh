#!/bin/bash
# s17: cellMesh quarter3D with azimuthSize 1e-9
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict mode quarter3D; echo "azimuthSize 1e-9;" >> system/cellMeshDict
timeout 60 cellMesh > log.cm 2>&1; rc=$?; grep -A3 "FATAL" log.cm | head -4; echo "rc=$rc"
