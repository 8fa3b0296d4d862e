#!/bin/bash
# b15 (class 1+4, pulseStudy: the base case includes a file by a RELATIVE path leaving its folder): $W/base (the preview tutorial) whose solidProperties materials{} hold `#sinclude "../../shared/override"` ($W/shared/override, next to the base case: a second Maxwell branch of the membrane, mu2 50 tau2 1e-9), which the base case run where it is reads; pulseStudy (one point, -keep): the point runs with the override (its log lists the second branch), or the study refuses/says that the include resolves elsewhere from its copy; never the point silently without it?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; mkdir -p $W/shared; printf 'membrane { mu2 50; tau2 1e-9; }\n' > $W/shared/override
sed -i 's|^\( *\)#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"|&\n\1#sinclude "../../shared/override"|' $W/base/constant/solidProperties; grep -a -n 'override' $W/base/constant/solidProperties
(cd $W/base/constant && echo "   from the base case: $(foamDictionary -expand solidProperties 2>/dev/null | grep -a -c 'mu2')" mu2 line)
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict
run 250 pulseStudy -case . -keep > ../log.s 2>&1; grep -a -m4 -i 'error\|refus\|done\|include\|outside' ../log.s | cut -c1-240
echo "   the point's membrane: $(grep -a -h -m1 'membrane' postProcessing/pulseStudy/points/*/case/log.cellBlastFoam 2>/dev/null | cut -c1-200)"
