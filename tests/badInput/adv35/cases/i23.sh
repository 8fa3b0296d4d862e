#!/bin/bash
# i23: ind: mesh type unknown
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/type        gmsh;/type gmsh2;/' constant/solidProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
