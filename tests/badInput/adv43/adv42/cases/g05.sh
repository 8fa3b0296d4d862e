#!/bin/bash
# g05 (class 1, the pulse through a file): the top patch's pulse read by OpenFOAM's tableFile (uniformValue tableFile; uniformValueCoeffs { file ...; }) from (a) constant/pulse.dat (directly in constant/), (b) constant/tables/pulse.dat (a sub-folder of constant/). Finished to 2 ns; the file's plateau changed 50 -> 60 MPa (its first rows unchanged), restart to 3 ns: refused naming the pulse file, or continued with the new pulse (exit 0)?
. "$(dirname "$0")/../lib.sh"
blastRef
mk() { /usr/bin/python3 - 0/p "$1" <<'P'
import re, sys
p, f = sys.argv[1], sys.argv[2]; t = open(p).read()
t = re.sub(r'uniformValue\s+table\s*\((?:\s*\([^()]*\))*\s*\);', 'uniformValue tableFile;\n        uniformValueCoeffs { file "$FOAM_CASE/%s"; }' % f, t, 1); open(p, 'w').write(t)
P
  mkdir -p $(dirname $1); printf '(\n (0 0)\n (1e-10 5e7)\n (5e-09 5e7)\n (5.1e-09 0)\n (1 0)\n)\n' > $1; }
for f in constant/pulse.dat constant/tables/pulse.dat; do
  cd $W; rm -rf blast; blast; mk $f; sed -n '/top/,/}/p' 0/p | grep -a 'uniformValue' | tr -s ' ' | tr '\n' ' '; echo
  run 120 cellBlastFoam > log.first 2>&1; fatal log.first 3; echo "   $f: first run, times $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; grep -a 'uniformValue\|file' 2e-09/p | head -3 | tr -s ' ' | tr '\n' ' '; echo
  latest; blastEnd 3e-9 1e-9; sed -i 's/5e7/6e7/g' $f; sums > ../s
  tryf "   $f plateau 5e7 -> 6e7, restart" cellBlastFoam; grep -a -A3 'other inputs' $W/try.log | head -4 | cut -c1-200; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; nochange ../s
  [ -d 3e-09 ] && echo "   3e-09: top patch p $(foamDictionary -entry boundaryField/top/value -value 3e-09/p 2>&1 | head -1 | cut -c1-60) (clean restart: $(foamDictionary -entry boundaryField/top/value -value $W/r/ref/3e-09/p 2>&1 | head -1 | cut -c1-60)); $(cmpRef $W/r/ref)"
done
