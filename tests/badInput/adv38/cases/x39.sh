#!/bin/bash
# x39: blast finished to 2 ns; 0/p's top given with the same condition written differently: the table rows as 'table ( (0 0) ... )' on one line and with 5e+07 for 5e7 (same numbers): restart accepted? and 0/p internalField 'uniform 0' -> 'nonuniform List<scalar> N(0 ... 0)' (same values): accepted?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp 0/p ../p0
/usr/bin/python3 - <<'P'
import re
s=open('0/p').read(); m=re.search(r'uniformValue\s+table\s*\(.*?\n\s*\);', s, re.S)
rows=re.findall(r'\(\s*([^()\s]+)\s+([^()\s]+)\s*\)', m.group(0))
one='uniformValue table (' + ' '.join('(%r %r)'%(float(a),float(b)) for a,b in rows) + ');'
open('0/p','w').write(s[:m.start()]+one+s[m.end():])
P
grep -a "uniformValue" 0/p | cut -c1-150; try "table respelt" cellBlastFoam; rm -rf 3e-09; cp ../p0 0/p
n=$(/usr/bin/python3 -c "import re;s=open('constant/polyMesh/owner').read();print(max(int(x) for x in re.search(r'\n(\d+)\s*\n\(',s).group(0).split()[:1]) if 0 else '')" 2>/dev/null); n=$(grep -a -m1 -A1 "^internalField" 1e-09/p | grep -o "^[0-9]*" | head -1); [ -z "$n" ] && n=$(sed -n '/^internalField/{n;p}' 1e-09/p | head -1)
echo "cells $n"; /usr/bin/python3 - $n <<'P'
import sys,re
n=int(sys.argv[1]); s=open('0/p').read(); s=re.sub(r'internalField\s+uniform\s+0;', 'internalField nonuniform List<scalar> %d(%s);' % (n, ' '.join(['0']*n)), s); open('0/p','w').write(s)
P
grep -a -c nonuniform 0/p; try "internalField nonuniform same values" cellBlastFoam
