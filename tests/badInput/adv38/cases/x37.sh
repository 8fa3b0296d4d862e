#!/bin/bash
# x37: blast: 0/p's pulse table moved into an #include'd file 0/pulseTable BEFORE the run (same values), run to 2 ns; then the user edits 0/pulseTable (the pulse's end 5 -> 3 ns) and restarts to 3 ns: refused naming 0/p (as the w18 edit in 0/p itself), or not seen?
. "$(dirname "$0")/../lib.sh"
blast; /usr/bin/python3 - <<'P'
import re
s=open('0/p').read(); m=re.search(r'uniformValue\s+table\s*(\(.*?\n\s*\));', s, re.S)
open('0/pulseTable','w').write('pulse '+m.group(1)+';\n'); open('0/p','w').write(s[:m.start()]+'#include "pulseTable"\n        uniformValue    table $pulse;'+s[m.end():])
P
grep -a -B1 -A1 'pulseTable' 0/p; run 60 cellBlastFoam > log.first 2>&1; tail -1 log.first; fatal log.first 3
sed -i 's/(5e-09 *50000000)/(3e-09 50000000)/; s/(5.1e-09 *0)/(3.1e-09 0)/' 0/pulseTable; cat 0/pulseTable | tr -s ' \n' ' '; echo; latest; blastEnd 3e-9 1e-9
run 60 cellBlastFoam > log.r 2>&1; tail -1 log.r; fatal log.r 6
