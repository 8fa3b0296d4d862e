#!/bin/bash
# v47: duplicates: constant/solidProperties, an override of the nucleus after the material set's #include with C10 given twice
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's|^\( *#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"\)|\1\n    nucleus { C10 7; C10 8; }|' constant/solidProperties; grep -n "C10 7" constant/solidProperties; cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"; grep nucleus postProcessing/indentation/materials.dat 2>/dev/null
