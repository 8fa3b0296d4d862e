#!/bin/bash
# s03: cellMesh contactSize 1e-10
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict contactSize 1e-10
timeout 60 cellMesh > log.cm 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.cm | head -8; tail -2 log.cm; echo "rc=$rc"
