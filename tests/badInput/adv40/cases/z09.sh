#!/bin/bash
# z09: indentation finished (smoke table, 4 rows); a 5th row appended (C1 load again) and startFrom latestTime: continues from the table's end (by design: rows after the checkpoint's may change)? force.dat and peaks.dat then equal, row for row, to a fresh run of the 5-row table?
. "$(dirname "$0")/../lib.sh"
ind; cp -r $W/ind $W/fresh; cellIndentationFoam > log.first 2>&1; echo "first: $(tail -1 log.first)"
add='    (C1  load    10e-6   0.5e-6)'
for c in $W/ind $W/fresh; do /usr/bin/python3 - $c/constant/indenterProperties "$add" <<'P'
import sys,re; f=sys.argv[1]; s=open(f).read(); i=s.index('protocol'); j=s.index(');', i); s=s[:j]+sys.argv[2]+'\n'+s[j:]; open(f,'w').write(s)
P
done; sed -n '/^protocol/,/);/p' constant/indenterProperties | tr '\n' ' '; echo
latest; try "restart with a 5th row" cellIndentationFoam
(cd $W/fresh && cellIndentationFoam > log.fresh 2>&1; echo "fresh 5-row run: rc=$? $(tail -1 log.fresh)")
for f in force.dat peaks.dat; do /usr/bin/python3 - $W/ind/postProcessing/indentation/$f $W/fresh/postProcessing/indentation/$f <<'P'
import sys, numpy as np
def rows(p): return [l.split() for l in open(p) if l.strip() and not l.startswith('#')]
a, b = rows(sys.argv[1]), rows(sys.argv[2])
same = a == b
print(sys.argv[1].split('/')[-1], 'restarted', len(a), 'rows, fresh', len(b), 'rows:', 'identical' if same else 'DIFFER')
if not same:
    for k,(x,y) in enumerate(zip(a,b)):
        if x != y: print('   first difference at row', k, x[:4], y[:4]); break
P
done
