#!/bin/bash
# i08: ind: protocol empty
. "$(dirname "$0")/../lib.sh"
ind; /usr/bin/python3 -c "import re;f='constant/indenterProperties';s=open(f).read();s=re.sub(r'protocol\s*\(.*?\n\);','protocol ();',s,flags=re.S);open(f,'w').write(s)"; grep protocol constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
