#!/bin/bash
# a01 (class 1, pulseStudy, k23's root through an ENVIRONMENT VARIABLE): the base case's constant/solidProperties #includes its material set as "$ADV44MAT/set" (exported; outside the base case); one point (30 MPa, 2 ns) finished; the set's first C10 (membrane's) x1e4; grid 30e6 -> (30e6 40e6); ./Allrun -keep: refused naming the changed input, or the new point run with the other set (its log.cellBlastFoam's C10) and nothing said?
. "$(dirname "$0")/../lib.sh"
export ADV44MAT=$W/mat; mkdir -p $ADV44MAT; cp "$ROOT/etc/caseDicts/cellMaterials/textFactor4" $ADV44MAT/set; cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base
sed -i 's|#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"|#include "$ADV44MAT/set"|' $W/base/constant/solidProperties; echo "   base includes: $(grep -a '#include' $W/base/constant/solidProperties | tr -s ' ')"
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m3 'error\|done\|points' ../log.s1 | cut -c1-160 | tr '\n' '|')"
/usr/bin/python3 - $ADV44MAT/set <<'P'
import re, sys; p = sys.argv[1]; t = open(p).read(); m = re.search(r'(C10\s+)([0-9.eE+-]+)', t); print('   changed in the set:', m.group(0), '-> x1e4'); t = t[:m.start(2)] + repr(1e4 * float(m.group(2))) + t[m.end(2):]; open(p, 'w').write(t)
P
setStudy overpressure "(30e6 40e6)"; run 250 ./Allrun -keep > ../log.s2 2>&1; echo "   rc above; again: $(grep -a -i -m5 'error\|refus\|differ\|changed\|done\|not run' ../log.s2 | cut -c1-220 | tr '\n' '|')"
echo "   points: $(ls postProcessing/pulseStudy/points | tr '\n' ' '); table rows: $(tail -n +2 postProcessing/pulseStudy/table.csv 2>/dev/null | grep -vc '^#')"
l=postProcessing/pulseStudy/points/p4e+07_T2e-09/case/log.cellBlastFoam; [ -f $l ] && echo "   the new point's solver read C10: $(grep -a -m3 -i 'C10' $l | tr -s ' ' | cut -c1-120 | tr '\n' '|')"
