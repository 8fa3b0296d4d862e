#!/bin/bash
# i43: cellMeshDict: cellHeight 0
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict cellHeight 0
cellMesh > log.cm 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.cm | head -8; tail -2 log.cm; echo "rc=$rc"
