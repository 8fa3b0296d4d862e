#!/bin/bash
# b39: blast: 0/p duplicated uniformValue, the constant LAST (the pulse table silently replaced?)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^\(        \);$/&/' 0/p; python3 - <<'P'
s=open('0/p').read(); i=s.index('uniformValue    table'); j=s.index(');', i)+2
s=s[:j]+'\n        uniformValue constant 1e6;'+s[j:]; open('0/p','w').write(s)
P
grep -n uniformValue 0/p
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; grep -i "pulse\|top" log.run | head -3
grep -a -A3 "^    top" 2e-09/p | head -4; grep -a "value" 2e-09/p | grep -a uniform | head -3
