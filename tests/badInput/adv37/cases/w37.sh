#!/bin/bash
# w37: ind killed at 2 s, the material set changed (#include textFactor4 -> table) in solidProperties, restart: refused?
. "$(dirname "$0")/../lib.sh"
indKilled 2; grep -n "cellMaterials" constant/solidProperties; sed -i 's/cellMaterials\/[A-Za-z0-9]*"/cellMaterials\/table"/' constant/solidProperties; grep -n "cellMaterials" constant/solidProperties
run 120 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
