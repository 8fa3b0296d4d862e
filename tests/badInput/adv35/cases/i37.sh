#!/bin/bash
# i37: cellMeshDict: cellDiameter given twice
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^cellDiameter .*/cellDiameter 16.8e-6;\ncellDiameter 20e-6;/' system/cellMeshDict
cellMesh > log.cm 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.cm | head -8; tail -2 log.cm; echo "rc=$rc"
