#!/bin/bash
# g07 (class 1, files under constant/ read implicitly): finished blast to 2 ns, in copies, restart to 3 ns after: (a) the water's mieGruneisenCoeffs moved into a sub-folder file constant/water/eos (#include "water/eos", the same numbers: accepted?) and then C0 1450 -> 1460 in that file (refused naming thermophysicalProperties?); (b) constant/polyMesh/boundary's top patch given "inGroups 1(wall);"; (c) a constant/fsiProperties.allrun of the user's (read by the #sinclude) with coupling { solidSubcycles 2; }
. "$(dirname "$0")/../lib.sh"
blastDone; cd ..; for c in a b c; do cp -r blast $c; done
cd a; latest; blastEnd 3e-9 1e-9; mkdir -p constant/water; /usr/bin/python3 - constant/thermophysicalProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); m = re.search(r'mieGruneisenCoeffs\s*\{[^{}]*\}', t)
open('constant/water/eos', 'w').write(m.group(0) + '\n'); open(p, 'w').write(t[:m.start()] + '#include "water/eos"' + t[m.end():])
P
cp -r . ../a2; tryf "(a0) the same coefficients moved to constant/water/eos" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
cd ../a2; sed -i 's/C0 *1450;/C0 1460;/' constant/water/eos; grep C0 constant/water/eos | tr -s ' '; sums > ../s.a; tryf "(a) C0 1450 -> 1460 in constant/water/eos" cellBlastFoam; grep -a -A3 'other inputs' $W/try.log | tail -3 | cut -c1-200; nochange ../s.a
cd ../b; latest; blastEnd 3e-9 1e-9; /usr/bin/python3 - constant/polyMesh/boundary <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); t = re.sub(r'(\n\s*top\s*\{\s*\n\s*type\s+patch;)', r'\1\n        inGroups        1(wall);', t, 1); open(p, 'w').write(t)
P
sums > ../s.b; tryf "(b) boundary: top inGroups 1(wall)" cellBlastFoam; grep -a -A3 'other inputs' $W/try.log | tail -3 | cut -c1-200; nochange ../s.b
cd ../c; latest; blastEnd 3e-9 1e-9; printf 'coupling\n{\n    solidSubcycles 2;\n}\n' > constant/fsiProperties.allrun; sums > ../s.c; tryf "(c) constant/fsiProperties.allrun solidSubcycles 2" cellBlastFoam; grep -a -A3 'other inputs' $W/try.log | tail -3 | cut -c1-200; nochange ../s.c
