#!/bin/bash
# i49: ind: case path with a double quote character
. "$(dirname "$0")/../lib.sh"
ind; cd ..; mv ind 'in"d'; cd 'in"d'
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -4; echo "rc=$rc"
