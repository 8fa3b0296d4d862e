#!/bin/bash
# y10: initial conditions in other spellings after a blast run to 2 ns, restart to 3 ns each: (a) 0/T's ".*" zeroGradient written out per patch (the same conditions): accepted? (b) 0/T internalField 293.15 as 2.9315e2: accepted? (c) 0/p's top as a tableFile whose DATA is then changed (50 -> 30 MPa): refused, or continued with the new pulse silently?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../keep
sed -i 's/^ *".\*" *{ type zeroGradient; }/    interface { type zeroGradient; } top { type zeroGradient; } bottom { type zeroGradient; } outer { type zeroGradient; }/' 0/T; grep -a -c zeroGradient 0/T; try "(a) 0/T per patch" cellBlastFoam
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; sed -i 's/uniform 293.15;/uniform 2.9315e2;/' 0/T; try "(b) 0/T 2.9315e2" cellBlastFoam
rm -rf $W/blast; blast; printf '(\n (0 0)\n (1e-10 5e7)\n (5e-09 5e7)\n (5.1e-09 0)\n (1 0)\n)\n' > constant/pulse
/usr/bin/python3 - <<'P'
import re; s=open('0/p').read(); i=s.index('uniformValue'); j=s.index(');', i)+2
s=s[:i]+'uniformValue tableFile;\n        uniformValueCoeffs { file "<constant>/pulse"; }'+s[j:]; open('0/p','w').write(s)
P
run 120 cellBlastFoam > log.first 2>&1; tail -1 log.first; fatal log.first 3; latest; blastEnd 3e-9 1e-9; sed -i 's/5e7/3e7/' constant/pulse
try "(c) tableFile data changed 50 -> 30 MPa" cellBlastFoam; grep -a -m1 -i "pulse\|tableFile" $W/try.log | cut -c1-200
