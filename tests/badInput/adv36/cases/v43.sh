#!/bin/bash
# v43: duplicates: 0/p patch top written twice (the second block only 'uniformValue constant 1e6;')
. "$(dirname "$0")/../lib.sh"
blast; /usr/bin/python3 - <<'P'
s=open('0/p').read(); i=s.index('boundaryField'); j=s.index('{',i)+1; s=s[:j]+'\n    top\n    {\n        uniformValue constant 1e6;\n    }'+s[j:]; open('0/p','w').write(s)
P
cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 "FATAL" log.run | head -5 | cut -c1-300; echo "rc=$rc"
