#!/bin/bash
# v49: duplicates: sod (rhoRiemannFoam) 0/U, the first patch's type given twice
. "$(dirname "$0")/../lib.sh"
sod; /usr/bin/python3 - <<'P'
s=open('0/U').read(); i=s.index('boundaryField'); j=s.index('{',s.index('{',i)+1)+1; s=s[:j]+'\n        type fixedValue; value uniform (0 0 0);'+s[j:]; open('0/U','w').write(s)
P
sed -n '/boundaryField/,/}/p' 0/U | head -8; rhoRiemannFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"
