#!/bin/bash
# b18 (class 1, pulseStudy whose baseCase is a SYMBOLIC LINK retargeted): baseCase "$W/lnk" -> $W/baseA (the preview); one point finished; lnk retargeted to $W/baseB (the same preview with a second Maxwell branch of the membrane); a grid value added: refused naming what differs (the base case's files), or the new point run silently on the other base case, one table of two cells?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/baseA; cp -r $W/baseA $W/baseB; ln -s $W/baseA $W/lnk
sed -i 's|^\( *\)#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"|&\n\1membrane { mu2 50; tau2 1e-9; }|' $W/baseB/constant/solidProperties
study; sed -i "s|^baseCase .*|baseCase        \"$W/lnk\";|" system/pulseStudyDict
run 250 pulseStudy -case . > ../log.s1 2>&1; grep -a -m2 -i 'error\|done' ../log.s1 | cut -c1-200
ln -sfn $W/baseB $W/lnk; setStudy overpressure "(30e6 40e6)"; run 250 pulseStudy -case . -keep > ../log.s2 2>&1; grep -a -m3 -i 'error\|refus\|done\|differ' ../log.s2 | cut -c1-300
echo "   points: $(ls postProcessing/pulseStudy/points | tr '\n' ' '); table rows: $(grep -c . postProcessing/pulseStudy/table.csv 2>/dev/null); new point's membrane: $(grep -a -h -m1 'membrane' postProcessing/pulseStudy/points/p4e+07*/case/log.cellBlastFoam 2>/dev/null | cut -c1-160)"
