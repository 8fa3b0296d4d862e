#!/bin/bash
# i38: cellMeshDict: mode unknown
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict mode axisymetric
cellMesh > log.cm 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.cm | head -8; tail -2 log.cm; echo "rc=$rc"
