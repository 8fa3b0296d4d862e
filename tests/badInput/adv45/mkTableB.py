#!/usr/bin/python3
"""mkTableB.py [VERDICTS]: the table of adv45's new cases from verdictsB.txt (default; the last line of an id wins): the
counts per verdict, then one row per case: id, class and question (the case's header, its first parenthesis), verdict, note."""
import sys, os, re, collections
here = os.path.dirname(os.path.abspath(__file__))
V = {}
for l in open(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, 'verdictsB.txt')):
    if l.startswith('#') or not l.strip(): continue
    i, v, n = [x.strip() for x in l.split(' | ', 2)]; V[i] = (v, n)
c = collections.Counter(v.split(' ')[0] for v, n in V.values())
W = ['OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR']
print('| cases | ' + ' | '.join(W) + ' |'); print('|' + ' --- |' * (len(W) + 1)); print('| %d | %s |' % (len(V), ' | '.join(str(c[w]) for w in W))); print()
print('| id | class, what | verdict | observed |'); print('| --- | --- | --- | --- |')
for i in sorted(V):
    h = open(os.path.join(here, 'cases', i + '.sh')).read().splitlines()[1]
    m = re.match(r'# \w+ \(([^)]*)\)', h); what = m.group(1) if m else ''
    v, n = V[i]; b = '**%s**' % v if not v.startswith('OK') else v
    print('| %s | %s | %s | %s |' % (i, what.replace('|', '/'), b, n.replace('|', '/')))
