#!/bin/bash
# s01: cellMesh nucleusSize 1e-9 (1e10-ish elements)
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict nucleusSize 1e-9
timeout 60 cellMesh > log.cm 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.cm | head -8; tail -2 log.cm; echo "rc=$rc"
