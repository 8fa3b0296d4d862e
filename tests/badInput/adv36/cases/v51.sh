#!/bin/bash
# v51: duplicates: 0/p uniformValue given again through an #include file inside the pulse patch (after the table)
. "$(dirname "$0")/../lib.sh"
blast; echo 'uniformValue constant 1e6;' > 0/pulseOverride; /usr/bin/python3 - <<'P'
s=open('0/p').read(); i=s.index('uniformValue    table'); j=s.index(');',i)+2; s=s[:j]+'\n        #include "pulseOverride"'+s[j:]; open('0/p','w').write(s)
P
cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 "FATAL" log.run | head -5 | cut -c1-300; echo "rc=$rc"; echo "2e-09/p, patch top: $(sed -n '/^    top/,/}/p' 2e-09/p 2>/dev/null | grep -a uniformValue | head -2 | tr '\n' ' ')"
