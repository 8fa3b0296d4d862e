#!/bin/bash
# v74: duplicates: constant/dynamicMeshDict, a keyword given twice at the top level
. "$(dirname "$0")/../lib.sh"
blast; grep -v "^ *//" constant/dynamicMeshDict | grep -v "^$" | sed -n 8,14p; k=$(grep -v "^ *//\|^ *$\|FoamFile\|[{}]\|version\|format\|class\|object\|location" constant/dynamicMeshDict | head -1 | awk '{print $1}'); v=$(grep -m1 "^ *$k " constant/dynamicMeshDict | sed "s/^ *$k *//"); echo "key $k value $v"; echo "$k $v" >> constant/dynamicMeshDict
cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"
