#!/bin/bash
# i50: ind: a 3D (quarter3D) cell mesh in the axisymmetric indentation case
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict mode quarter3D; cellMesh > log.cm 2>&1; echo "cellMesh rc=$?"; tail -1 log.cm
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -1 log.run; echo "rc=$rc"
