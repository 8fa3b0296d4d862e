#!/bin/bash
# i44: cellMeshDict: membraneThickness larger than the cell height
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict membraneThickness 10e-6
cellMesh > log.cm 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.cm | head -8; tail -2 log.cm; echo "rc=$rc"
