#!/bin/bash
# i16: ind: mesh file empty
. "$(dirname "$0")/../lib.sh"
ind; : > constant/cell.msh
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
