#!/bin/bash
# d02 (class 1, indentation restart, a material read through $PROJECT_DIR): the killed smoke indentation restarted with PROJECT_DIR at a copy of etc/ whose textFactor4 nucleus mu1 is 500 (was 431.12): (b) refused naming region and entry, nothing changed; (a) an identical copy: accepted, the run ends.
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/proj; cp -r $ROOT/etc $W/proj/; sed -i "s/mu1         431.12;/mu1         500;/" $W/proj/etc/caseDicts/cellMaterials/textFactor4; grep -c "mu1         500;" $W/proj/etc/caseDicts/cellMaterials/textFactor4
ik; sums > ../s0
PROJECT_DIR=$W/proj tryt 200 "(b) nucleus mu1 changed via PROJECT_DIR" cellIndentationFoam; cont; echo "   changed: $(changed ../s0)"
cp $ROOT/etc/caseDicts/cellMaterials/textFactor4 $W/proj/etc/caseDicts/cellMaterials/textFactor4
PROJECT_DIR=$W/proj tryt 200 "(a) identical copy" cellIndentationFoam; cont; after
