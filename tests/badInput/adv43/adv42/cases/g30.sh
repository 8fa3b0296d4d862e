#!/bin/bash
# g30 (class 1, rhoRiemannFoam, a file outside the case through #include): waterPulseWall's mieGruneisenCoeffs moved to ../shared/water (outside the case, #include "$FOAM_CASE/../shared/water"), run to 4e-8 s; restart to 6e-8 after (a) nothing changed: continues; (b) the shared file's C0 1450 -> 1451: refused naming constant/thermophysicalProperties?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/waterPulseWall" $W/wp; cd $W/wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1; mkdir -p ../shared
grep -n 'Coeffs' constant/thermophysicalProperties | head -3
/usr/bin/python3 - constant/thermophysicalProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); m = re.search(r'mieGruneisenCoeffs\s*\{[^{}]*\}', t)
if not m: print('   no mieGruneisenCoeffs'); sys.exit(0)
open('../shared/water', 'w').write(m.group(0) + '\n'); open(p, 'w').write(t[:m.start()] + '#include "$FOAM_CASE/../shared/water"' + t[m.end():])
P
sed -i "s/^endTime .*/endTime 4e-8;/" system/controlDict; run 200 rhoRiemannFoam > log.first 2>&1; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
latest; sed -i "s/^endTime .*/endTime 6e-8;/" system/controlDict; cd ..; cp -r wp wpb; cp -r shared sharedb; cd wp
tryf "(a) unchanged, restart" rhoRiemannFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
cd ../wpb; sed -i 's|\$FOAM_CASE/../shared/water|$FOAM_CASE/../sharedb/water|' constant/thermophysicalProperties; tryf "(a2) the same file content under another path" rhoRiemannFoam; rm -rf 6e-08 5e-08; ls -d [1-9]* | tail -1
sed -i 's/C0 *1450;/C0 1451;/' ../sharedb/water; grep C0 ../sharedb/water | tr -s ' '; sums > ../s.b; tryf "(b) C0 1450 -> 1451 in the shared file" rhoRiemannFoam; grep -a -A3 'other inputs' $W/try.log | tail -3 | cut -c1-200; nochange ../s.b
