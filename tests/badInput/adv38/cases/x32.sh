#!/bin/bash
# x32: blast finished to 2 ns, then foamFormatConvert (the user converts the times to binary to save space: every field rewritten): restart to 3 ns refused naming the rewritten files? with -acceptEdited: continued, and the 3-ns fields equal (to 1e-12) the run continued from the ascii times?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../asc; setd system/controlDict writeFormat binary; foamFormatConvert > log.conv 2>&1 || tail -3 log.conv; setd system/controlDict writeFormat ascii; head -c 400 2e-09/p | grep -a format
try "restart after foamFormatConvert" cellBlastFoam; grep -a -A5 "FATAL" $W/try.log | head -6 | cut -c1-200
run 120 cellBlastFoam -acceptEdited > log.acc 2>&1; tail -1 log.acc; fatal log.acc 4
cd ../asc; cellBlastFoam > log.r 2>&1; cd ../blast; /usr/bin/python3 - <<'P'
import re
def vals(f):
    s=open(f,errors='replace').read(); m=re.search(r'internalField\s+nonuniform\s+List<scalar>\s*\n?(\d+)\s*\(([^)]*)\)',s,re.S)
    return [float(x) for x in m.group(2).split()] if m else None
a=vals('3e-09/p'); b=vals('../asc/3e-09/p')
print('3e-09/p:', 'missing' if a is None or b is None else 'max |diff| %.3g Pa of %.3g' % (max(abs(x-y) for x,y in zip(a,b)), max(abs(y) for y in b)))
P
