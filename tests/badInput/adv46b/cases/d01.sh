#!/bin/bash
# d01 (class 1, blast restart, a material read through $PROJECT_DIR): the finished preview restarted (latestTime, to 3 ns) with PROJECT_DIR pointing at a copy of etc/ whose textFactor4 has cytoplasm C10 2.0 (was 1.67): (b) refused naming the material entry, nothing written; (a) then a copy identical to etc/: accepted (continues).
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/proj; cp -r $ROOT/etc $W/proj/; sed -i "0,/C10         1.67;/s//C10         2.0;/" $W/proj/etc/caseDicts/cellMaterials/textFactor4; grep -c "C10         2.0;" $W/proj/etc/caseDicts/cellMaterials/textFactor4
bd; rs; sums > ../s0
PROJECT_DIR=$W/proj tryt 240 "(b) PROJECT_DIR copy with C10 changed" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
cp $ROOT/etc/caseDicts/cellMaterials/textFactor4 $W/proj/etc/caseDicts/cellMaterials/textFactor4
PROJECT_DIR=$W/proj tryt 240 "(a) PROJECT_DIR copy identical" cellBlastFoam; cont; after
