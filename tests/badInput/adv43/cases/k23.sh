#!/bin/bash
# k23 (class 1 in pulseStudy, an input read from OUTSIDE the base case; added at the end): the study's base case a copy of the preview whose constant/solidProperties #includes its material set from a file outside it ($W/mat/set, a copy of etc/caseDicts/cellMaterials/textFactor4); one point finished; then one number of the set changed (the first C10, membrane's, x1e4: 166.67 Pa -> 1.67 MPa) and a grid value added (30e6 -> 30e6 40e6); the points run to 12 ns (the pulse reaches the cell after about 8 ns); ./Allrun: refused naming the changed input (as a change in the base case's own files is), or the new point run with the other materials and one table written from two material sets?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/mat; cp "$ROOT/etc/caseDicts/cellMaterials/textFactor4" $W/mat/set; cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; sed -i "s|#include \"\$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4\"|#include \"$W/mat/set\"|" $W/base/constant/solidProperties; grep -a -c "$W/mat/set" $W/base/constant/solidProperties
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; sed -i 's/-endTime 2e-9)/-endTime 12e-9)/' system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m2 'error\|done' ../log.s1 | cut -c1-160 | tr '\n' '|')"
/usr/bin/python3 - $W/mat/set <<'P'
import re, sys; p = sys.argv[1]; t = open(p).read(); m = re.search(r'(C10\s+)([0-9.eE+-]+)', t); print('   changed in the set:', m.group(0)); t = t[:m.start(2)] + repr(1e4 * float(m.group(2))) + t[m.end(2):]; open(p, 'w').write(t)
P
setStudy overpressure "(30e6 40e6)"; run 250 ./Allrun > ../log.s2 2>&1; echo "   again: $(grep -a -i -m4 'error\|refus\|differ\|changed\|done\|not run' ../log.s2 | cut -c1-220 | tr '\n' '|')"; echo "   points: $(ls postProcessing/pulseStudy/points | tr '\n' ' '); table rows: $(tail -n +2 postProcessing/pulseStudy/table.csv 2>/dev/null | grep -vc '^#')"
# proof that the new point ran with the changed set: the same study from scratch with the ORIGINAL set for 40 MPa only; the p4e+07 results compared
cd $W; mv study study1; R=$W/study1; cp "$ROOT/etc/caseDicts/cellMaterials/textFactor4" $W/mat/set; study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; setStudy overpressure "(40e6)"; sed -i 's/-endTime 2e-9)/-endTime 12e-9)/' system/pulseStudyDict; run 250 ./Allrun > ../log.s3 2>&1 > /dev/null
/usr/bin/python3 - $R/postProcessing/pulseStudy/points/p4e+07_T2e-09/result.json postProcessing/pulseStudy/points/p4e+07_T2e-09/result.json <<'P'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
def flat(d, k=''):
    if isinstance(d, dict):
        for x, y in d.items(): yield from flat(y, k + '/' + x)
    else: yield k, d
fa, fb = dict(flat(a)), dict(flat(b)); diff = [k for k in fa if k in fb and fa[k] != fb[k] and 'digest' not in k and 'wall' not in k and 'cpu' not in k.lower()]
print('   p4e+07 result with the changed set vs the original set: %d of %d entries differ%s' % (len(diff), len(fa), (' (e.g. ' + ', '.join(diff[:4]) + ')') if diff else ''))
P
