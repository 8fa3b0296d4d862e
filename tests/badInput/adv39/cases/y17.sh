#!/bin/bash
# y17: the same pulse in another spelling after a run to 2 ns: 0/p's top table moved to constant/pulse as a tableFile (same rows), restart to 3 ns: accepted (the same condition) or refused naming what (a wrong reason)?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; sed -n '/uniformValue/,/);/p' 0/p | tr -s ' \n' ' '; echo
/usr/bin/python3 - <<'P'
s=open('0/p').read(); i=s.index('uniformValue'); j=s.index(');', i)+2; t=s[i:j]; rows=t[t.index('('):t.rindex(')')+1]
open('constant/pulse','w').write(rows+'\n'); s=s[:i]+'uniformValue tableFile;\n        uniformValueCoeffs { file "<constant>/pulse"; }'+s[j:]; open('0/p','w').write(s)
P
cat constant/pulse | tr -s ' \n' ' '; echo; try "table -> tableFile (same rows)" cellBlastFoam; grep -a -A3 "other inputs" $W/try.log | head -4 | cut -c1-200
