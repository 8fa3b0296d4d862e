#!/bin/bash
# a39 (class 1, pulseStudy, an include TWO levels outside the base case): the base case's constant/solidProperties #includes $W/mat/set (outside), which #includes $W/mat/membrane (the membrane's entries moved there); one point finished; the membrane's C10 x1e4 in $W/mat/membrane; a grid value added; ./Allrun -keep: refused naming $W/mat/membrane, or the new point run with the other membrane?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/mat; cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; S="$ROOT/etc/caseDicts/cellMaterials/textFactor4"
/usr/bin/python3 - "$S" $W/mat <<'PY'
import re, sys; src, d = sys.argv[1], sys.argv[2]; t = open(src).read()
m = re.search(r'\n(\s*membrane\s*\{[^{}]*\})', t); open(d + '/membrane', 'w').write(m.group(1) + '\n'); open(d + '/set', 'w').write(t[:m.start(1)] + '#include "' + d + '/membrane"\n' + t[m.end(1):])
print('   membrane moved to', d + '/membrane:', ' '.join(m.group(1).split())[:120])
PY
sed -i "s|#include \"\$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4\"|#include \"$W/mat/set\"|" $W/base/constant/solidProperties
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m3 'error\|done' ../log.s1 | cut -c1-160 | tr '\n' '|')"
sed -i 's/\(C10 *\)\([0-9.]*\)/\1\2e4/' $W/mat/membrane; echo "   changed: $(grep -a C10 $W/mat/membrane | tr -s ' ')"
setStudy overpressure "(30e6 40e6)"; run 250 ./Allrun -keep > ../log.s2 2>&1; echo "   again: $(grep -a -i -m5 'error\|refus\|differ\|changed\|done\|not run' ../log.s2 | cut -c1-240 | tr '\n' '|')"
l=postProcessing/pulseStudy/points/p4e+07_T2e-09/case/log.cellBlastFoam; [ -f $l ] && echo "   the new point's solver read: $(grep -a -m3 -i 'C10' $l | tr -s ' ' | cut -c1-90 | tr '\n' '|')"
