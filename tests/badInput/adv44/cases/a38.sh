#!/bin/bash
# a38 (class 1, pulseStudy, an OPTIONAL include outside the base case that appears later): the base case's constant/solidProperties ends with `#sinclude "$W/opt/override"` (absent: nothing included); one point finished; the user then creates that file with `materials { membrane { C10 1666.7; } }`; a grid value added; ./Allrun -keep: refused naming the file that appeared, or the new point run with the other membrane (its log's C10)?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/opt; cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; echo "#sinclude \"$W/opt/override\"" >> $W/base/constant/solidProperties
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m3 'error\|done' ../log.s1 | cut -c1-160 | tr '\n' '|')"
echo 'materials { membrane { C10 1666.7; } }' > $W/opt/override
setStudy overpressure "(30e6 40e6)"; run 250 ./Allrun -keep > ../log.s2 2>&1; echo "   again: $(grep -a -i -m5 'error\|refus\|differ\|changed\|done\|not run' ../log.s2 | cut -c1-240 | tr '\n' '|')"
l=postProcessing/pulseStudy/points/p4e+07_T2e-09/case/log.cellBlastFoam; [ -f $l ] && echo "   the new point's solver read: $(grep -a -m3 -i 'C10' $l | tr -s ' ' | cut -c1-90 | tr '\n' '|')"
