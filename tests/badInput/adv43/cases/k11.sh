#!/bin/bash
# k11 (class 1, a tableFile read from OUTSIDE constant/): the top patch's pulse as tableFile from (a) system/tables/pulse.dat, (b) a file outside the case ($FOAM_CASE/../shared/pulse.dat), (c) constant/tables/deep/er/pulse.dat (two levels down); finished to 2 ns, the plateau 50 -> 60 MPa, restart to 3 ns: refused naming the file? (d) control: the same file touched only (no change): continues, equal to a clean restart?
. "$(dirname "$0")/../lib.sh"
blastRef
mk() { /usr/bin/python3 - 0/p "$1" <<'P'
import re, sys
p, f = sys.argv[1], sys.argv[2]; t = open(p).read()
t = re.sub(r'uniformValue\s+table\s*\((?:\s*\([^()]*\))*\s*\);', 'uniformValue tableFile;\n        uniformValueCoeffs { file "%s"; }' % f, t, 1); open(p, 'w').write(t)
P
  local r=${1//\$FOAM_CASE/$PWD}; mkdir -p $(dirname $r); printf '(\n (0 0)\n (1e-10 5e7)\n (5e-09 5e7)\n (5.1e-09 0)\n (1 0)\n)\n' > $r; echo $r; }
for f in '$FOAM_CASE/system/tables/pulse.dat' '$FOAM_CASE/../shared/pulse.dat' '$FOAM_CASE/constant/tables/deep/er/pulse.dat' 'touch:$FOAM_CASE/constant/tables/deep/er/pulse.dat'; do
  cd $W; rm -rf blast shared; blast; g=${f#touch:}; r=$(mk "$g"); grep -a -c tableFile 0/p
  run 120 cellBlastFoam > log.first 2>&1; fatal log.first 3; echo "   $f: first run, times $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"
  latest; blastEnd 3e-9 1e-9; if [ "$g" = "$f" ]; then sed -i 's/5e7/6e7/g' $r; else sleep 1; touch $r; fi; sums > ../s
  tryf "   $f: plateau 5e7 -> 6e7 (touch: unchanged), restart" cellBlastFoam; grep -a -A3 'other inputs' $W/try.log | head -4 | cut -c1-200; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; nochange ../s
  [ -d 3e-09 ] && cmpRef $W/r/ref
done
