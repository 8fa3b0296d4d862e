#!/usr/bin/python3
"""mkTableZ.py: phase 2's table (out/Z, the fix19c merge) from verdictsZ.py: counts, then one row per case"""
import os, collections
here = os.path.dirname(os.path.abspath(__file__)); exec(open(os.path.join(here, 'verdictsZ.py')).read())
W = ['OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR']; c = collections.Counter(v.split(' ')[0] for v, n in VZ.values())
print('| cases | ' + ' | '.join(W) + ' |'); print('|' + ' --- |' * (len(W) + 1)); print('| %d | %s |' % (len(VZ), ' | '.join(str(c[w]) for w in W)))
print(); print('| case | verdict on the merge | observed |'); print('| --- | --- | --- |')
for k, (v, n) in VZ.items(): print('| %s | %s | %s |' % (k.replace('_', ' '), ('**%s**' % v) if v != 'OK' else v, n))
