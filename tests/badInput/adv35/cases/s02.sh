#!/bin/bash
# s02: cellMesh membraneLayers 100000
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict membraneLayers 100000
timeout 60 cellMesh > log.cm 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.cm | head -8; tail -2 log.cm; echo "rc=$rc"
