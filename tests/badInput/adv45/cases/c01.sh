#!/bin/bash
# c01 (phase 2, class 1+4, false alarms of fix19b's refusal of location-dependent includes; written from fix19b-fixed.md's b15 line only): pulseStudy (one point) whose base case's constant/solidProperties materials{} #sincludes, in turn, (a) "$FOAM_CASE/constant/override" (inside the case: the OpenFOAM idiom), (b) "../constant/override" from constant/ (a relative path that leaves and re-enters the folder), (c) an absolute path outside ($W/shared/override, digested by design): each run (the point's membrane shows the override's second branch) or refused naming the include and why; never the point silently without the override?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; mkdir -p $W/shared; printf 'membrane { mu2 50; tau2 1e-9; }\n' | tee $W/base/constant/override > $W/shared/override; cp $W/base/constant/solidProperties $W/sp.orig
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict
for inc in '$FOAM_CASE/constant/override' '../constant/override' "$W/shared/override"; do cp $W/sp.orig $W/base/constant/solidProperties
  sed -i "s|^\( *\)#include \"\$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4\"|&\n\1#sinclude \"$inc\"|" $W/base/constant/solidProperties; grep -a -c 'sinclude.*override' $W/base/constant/solidProperties | sed 's/^/   include lines: /'
  rm -rf postProcessing; run 250 pulseStudy -case . -keep > ../log.s 2>&1; echo "[$inc] $(grep -a -m2 -i 'error\|refus\|done' ../log.s | cut -c1-260 | tr '\n' '|')"
  echo "   the point's membrane: $(grep -a -h -m1 'membrane' postProcessing/pulseStudy/points/*/case/log.cellBlastFoam 2>/dev/null | cut -c1-160)"; done
