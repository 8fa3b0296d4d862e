#!/bin/bash
# CASETIMEOUT=900
# h08 (class 4, numberText's edges, fix19d/804c109d: every C++ tool that prints a refused number, given -DBL_MAX, DBL_MAX,
# 1e308, -1e308, 1e309, inf, -inf, nan, -0, 4.9e-324, 1e-310): rhoRiemannFoam maxCo (sod controlDict), cellBlastFoam
# coupling tolerance (constant/fsiProperties) and endTime (system/controlDict.allrun), cellIndentationFoam tolerance
# (constant/indenterProperties) and the membrane's mu1 (a copy of textFactor4 included from constant/mats), cellMesh
# cellHeight. Each value refused (rc 1, no signal) naming the file, the entry and the valid range, the value printed
# as given (never as a number inside the range), or accepted if in range (then cut at 30 s). One line per run.
. "$(dirname "$0")/../lib.sh"
V="-1.7976931348623157e308 1.7976931348623157e308 1e308 -1e308 1e309 inf -inf nan -0 4.9e-324 1e-310"
show() { local rc=$1; echo "   [$2] rc=$rc sig=$(sig) | $(grep -a -m1 -A2 'FATAL\|[Ee]rror\|refused\|outside\|not a\|invalid' $W/try.log | grep -av '^ *$\|^-->\|From function\|^\[.\] *$' | head -2 | tr '\n' ' ' | tr -s ' ' | cut -c1-330)"; }
each() { local label=$1 file=$2 key=$3 cmd=$4; echo "== $label: $key in $file"; cp $file $W/orig
  for v in $V; do cp $W/orig $file; sete $file $key $v; timeout -s KILL 30 $cmd > $W/try.log 2>&1; show $? "$v"; rm -rf [1-9]* 0.[0-9]* postProcessing solid; done; cp $W/orig $file; }
sod; each "rhoRiemannFoam" system/controlDict maxCo rhoRiemannFoam
cd $W; blast; each "cellBlastFoam" constant/fsiProperties tolerance cellBlastFoam
printf 'endTime 2e-9;\nwriteInterval 1e-9;\n' > system/controlDict.allrun; each "cellBlastFoam" system/controlDict.allrun endTime cellBlastFoam
cd $W; ind; each "cellIndentationFoam" constant/indenterProperties tolerance cellIndentationFoam
grep -v '^ *//' $ROOT/etc/caseDicts/cellMaterials/textFactor4 > constant/mats; sed -i 's|#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"|#include "mats"|' constant/solidProperties; grep -c '#include "mats"' constant/solidProperties
each "cellIndentationFoam (materials)" constant/mats mu1 cellIndentationFoam
cd $W; rm -rf ind; ind; each "cellMesh" system/cellMeshDict cellHeight cellMesh
