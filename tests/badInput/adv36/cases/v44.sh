#!/bin/bash
# v44: duplicates: 0/p uniformValue given twice inside a regex patch entry "(top|outer)" (documented: patterns are not walked)
. "$(dirname "$0")/../lib.sh"
blast; /usr/bin/python3 - <<'P'
s=open('0/p').read(); s=s.replace('    top\n','    "(top)"\n',1); i=s.index('uniformValue    table'); j=s.index(');',i)+2; s=s[:j]+'\n        uniformValue constant 1e6;'+s[j:]; open('0/p','w').write(s)
P
grep -n '"(top)"\|uniformValue' 0/p; cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 "FATAL" log.run | head -5 | cut -c1-300; echo "rc=$rc"; grep -a -c "1000000\|1e+06" 2e-09/p 2>/dev/null
