#!/bin/bash
# x75: blast finished to 2 ns; 0/p's top table rewritten in OpenFOAM's list form with its size, 'table 5((0 0) (1e-10 50000000) ...)', the same rows (the form decomposePar and the solver write): restart to 3 ns accepted, or refused as a changed initial condition (the digest of the text, not of the condition)?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; /usr/bin/python3 - <<'P'
import re
s=open('0/p').read(); m=re.search(r'(uniformValue\s+table\s*)(\(.*?\n\s*\));', s, re.S)
rows=re.findall(r'\([^()]*\)', m.group(2)); open('0/p','w').write(s[:m.start()]+'uniformValue table\n%d\n(\n%s\n);' % (len(rows), '\n'.join(rows))+s[m.end():])
P
grep -a -A8 "uniformValue" 0/p | tr -s ' \n' ' '; echo; try "table with its size" cellBlastFoam
