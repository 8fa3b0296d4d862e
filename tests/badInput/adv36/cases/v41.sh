#!/bin/bash
# v41: duplicates: 0/U, patch top: 'type' given twice (slip, then zeroGradient)
. "$(dirname "$0")/../lib.sh"
blast; /usr/bin/python3 - <<'P'
s=open('0/U').read(); i=s.index('top'); j=s.index('{',i)+1; s=s[:j]+'\n        type slip;'+s[j:]; open('0/U','w').write(s)
P
sed -n '/top/,/}/p' 0/U; cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 "FATAL" log.run | head -5 | cut -c1-300; echo "rc=$rc"
