#!/bin/bash
# a38 (class 1, pulseStudy, an OPTIONAL include outside the base case that appears later): the base case's constant/solidProperties' materials{} has, after the set's #include, `#sinclude "$W/opt/override"` (absent: nothing included); one point finished; the user then creates that file with `membrane { mu2 50; tau2 1e-9; }` (a second Maxwell branch of the membrane, entries the set does not give: no duplicate); a grid value added; ./Allrun -keep: refused naming the file that appeared, or the new point run with the other membrane (its log's membrane line)?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/opt; cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; sed -i "s|^\( *#include \"\$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4\"\)|\1\n    #sinclude \"$W/opt/override\"|" $W/base/constant/solidProperties; echo "   base: $(grep -a 'include' $W/base/constant/solidProperties | tr -s ' ' | tr '\n' ' ')"
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m3 'error\|done' ../log.s1 | cut -c1-160 | tr '\n' '|')"
echo 'membrane { mu2 50; tau2 1e-9; }' > $W/opt/override
setStudy overpressure "(30e6 40e6)"; run 250 ./Allrun -keep > ../log.s2 2>&1; echo "   again: $(grep -a -i -m5 'error\|refus\|differ\|changed\|done\|not run' ../log.s2 | cut -c1-240 | tr '\n' '|')"
l=postProcessing/pulseStudy/points/p4e+07_T2e-09/case/log.cellBlastFoam; [ -f $l ] && echo "   the new point's solver read: $(grep -a -m1 -i 'membrane:' $l | tr -s ' ' | cut -c1-200 | tr '\n' '|')"
