#!/bin/bash
# w105: blast pulse table in 0/p at the edges: times not increasing ((5e-09 5e7) before (1e-10 5e7)), an amplitude nan, an empty table (): refused naming 0/p, or run?
. "$(dirname "$0")/../lib.sh"
blast; cp 0/p ../p0; sed -i 's/(1e-10 *50000000)/(6e-09 50000000)/' 0/p; grep -a -A8 uniformValue 0/p | tr -s ' \n' ' '; echo; try "times not increasing" cellBlastFoam; rm -rf solid postProcessing [1-9]*
cp ../p0 0/p; sed -i 's/(1e-10 *50000000)/(1e-10 nan)/' 0/p; try "amplitude nan" cellBlastFoam; rm -rf solid postProcessing [1-9]*
cp ../p0 0/p; /usr/bin/python3 - <<'P'
import re; s=open('0/p').read(); s=re.sub(r'uniformValue\s+table\s*\(.*?\n\s*\);', 'uniformValue    table ();', s, count=1, flags=re.S); open('0/p','w').write(s)
P
grep -a "uniformValue" 0/p; try "table ()" cellBlastFoam
